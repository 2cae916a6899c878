"""The `isoform pipeline` command, the README's main job, run as a program:
the built-in phantom through contour, curvature, reduction, the side-vertex
surface and the comparison, every file it writes checked; a second run into
the same folder; a real input file; a folder that is a file. Shares
test_cli.py's helpers.

Usage: test_cli_pipeline.py ISOFORM_BINARY SHARED_DATA_DIR GROUP"""
import os
import sys

import test_cli as base
from test_cli import expect, run, run_json, data, leftovers, expect_failure, check_ply_mesh


PIPELINE_FILES = ["phantom.vdb", "phantom-contour.ply", "phantom-curvature.ply", "phantom-reduced.ply",
                  "phantom-smooth.ply", "phantom-study"]


def case_pipeline(tmp):
    folder = os.path.join(tmp, "out")
    report, _ = run_json("pipeline", "-o", folder)  # the README's main job, 128^3
    vdb, ply = os.path.join(folder, "phantom.vdb"), os.path.join(folder, "phantom-contour.ply")
    curved = os.path.join(folder, "phantom-curvature.ply")
    reduced, smooth = os.path.join(folder, "phantom-reduced.ply"), os.path.join(folder, "phantom-smooth.ply")
    study = os.path.join(folder, "phantom-study")
    expect(report["written"] == [vdb, ply, curved, reduced, smooth, os.path.join(study, "report.md")],
           f"written: {report['written']}")
    expect(leftovers(folder, PIPELINE_FILES) == [], f"left behind: {leftovers(folder, PIPELINE_FILES)}")
    _, _, _, parts = check_ply_mesh(ply, report["contour"])
    expect(len(set(parts)) >= 2, f"the skull gives {len(set(parts))} parts, expected 2 or more")
    c = report["curvature"]
    expect(c["vertices"] == report["contour"]["vertices"] and c["fallbacks"]["failed"] == 0, f"curvature: {c}")
    # The skull's outer surface dominates and is convex: the median H is positive.
    expect(c["mean"]["p50"] > 0, f"median mean curvature {c['mean']['p50']}")
    with open(curved, "rb") as f:
        header = f.read(2000).split(b"end_header")[0].decode("ascii")
    for prop in ("k1", "k2", "mean", "gauss", "absolute", "d1x", "d2z", "red", "alpha"):
        expect(f" {prop}\n" in header, f"phantom-curvature.ply has no vertex property {prop}")
    g = run_json("info", vdb)[0]["grids"][0]
    expect(g["scalar"] and g["active_voxels"] > 0, f"phantom.vdb: {g}")
    # Chapter 5: fewer triangles, still closed, the contour's parts kept.
    r = report["reduce"]
    expect(r["triangles_before"] == report["contour"]["triangles"] and
           r["triangles_after"] < 0.5 * r["triangles_before"], f"reduce: {r}")
    # (The reduced PLY carries curvature properties; the library reads it back.)
    read_back = run_json("patch", reduced, "--level", "0", "-o", os.path.join(tmp, "flat.ply"))[0]["input_mesh"]
    expect(read_back["triangles"] == r["triangles_after"] and read_back["parts"] == len(set(parts)) and
           read_back["boundary_edges"] == 0 and read_back["nonmanifold_edges"] == 0,
           f"{reduced} read back: {read_back}")
    # Chapter 6: 4^2 triangles per reduced triangle, closed.
    _, _, smooth_faces, _ = check_ply_mesh(smooth, report["smooth"])
    expect(len(smooth_faces) == 16 * r["triangles_after"], f"{smooth}: {len(smooth_faces)} triangles")
    # The study: three surfaces; the side-vertex one through the data points, Loop not.
    compare = report["compare"]
    expect(sorted(compare) == ["linear", "loop", "side-vertex"], f"compare: {sorted(compare)}")
    expect(compare["side-vertex"]["data_point_error"]["max"] < 1e-5 <
           compare["loop"]["data_point_error"]["max"], f"data point errors: {compare}")
    expect(compare["side-vertex"]["normal_gap"]["max"] < 1e-6, f"side-vertex normal gap {compare}")
    expect(sorted(os.listdir(study)) == ["report.json", "report.md", "samples.csv", "surface-linear.ply",
                                         "surface-loop.ply", "surface-side-vertex.ply"],
           f"{study}: {sorted(os.listdir(study))}")


def case_pipeline_again(tmp):
    folder = os.path.join(tmp, "out")
    run("pipeline", "-o", folder, "--size", "32", "--quiet")
    proc = run("pipeline", "-o", folder, "--size", "32", "--method", "tetra")
    expect("phantom-contour.ply" in proc.stdout, f"summary: {proc.stdout}")
    check_ply_mesh(os.path.join(folder, "phantom-contour.ply"))
    expect(sorted(os.listdir(folder)) == sorted(PIPELINE_FILES), f"folder holds {sorted(os.listdir(folder))}")


def case_pipeline_on_a_file(tmp):
    """pipeline sphere.vdb: files named after the input, the input untouched."""
    sphere = data("sphere.vdb")
    before = os.path.getmtime(sphere)
    folder = os.path.join(tmp, "out")
    report, _ = run_json("pipeline", sphere, "-o", folder, "--keep", "5%", "--level", "1")
    expect(report["input"] == sphere and report["contour"]["isovalue"] == 0.0, f"report: {report['contour']}")
    expect(sorted(os.listdir(folder)) == ["sphere-contour.ply", "sphere-curvature.ply", "sphere-reduced.ply",
                                          "sphere-smooth.ply", "sphere-study"],
           f"folder holds {sorted(os.listdir(folder))}")
    expect(os.path.getmtime(sphere) == before, "the input was touched")
    r = report["reduce"]
    expect(abs(r["triangles_after"] - 0.05 * r["triangles_before"]) <= 3, f"reduce: {r}")


def case_pipeline_folder_is_file(tmp):
    blocker = os.path.join(tmp, "file")
    with open(blocker, "w") as f:
        f.write("x")
    expect_failure(tmp, ["pipeline", "-o", blocker, "--size", "32"], ["file"], ["file"])


GROUPS = {
    "pipeline": [case_pipeline, case_pipeline_again, case_pipeline_on_a_file, case_pipeline_folder_is_file],
}


if __name__ == "__main__":
    base.run_groups(GROUPS, sys.argv)
