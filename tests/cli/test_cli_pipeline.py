"""The `isoform pipeline` command, the README's main job, run as a program:
the built-in phantom through contour, curvature, reduction, the side-vertex
surface and the comparison, every file it writes checked; a second run into
the same folder; a real input file; a folder that is a file. Shares
test_cli.py's helpers.

Usage: test_cli_pipeline.py ISOFORM_BINARY SHARED_DATA_DIR GROUP"""
import os
import sys

import numpy as np

import test_cli as base
from test_cli import expect, run, run_json, data, leftovers, expect_failure, check_ply_mesh


PIPELINE_FILES = ["phantom.vdb", "phantom-contour.ply", "phantom-curvature.ply", "phantom-reduced.ply",
                  "phantom-smooth.ply", "phantom-study", "phantom-report.html"]
PICTURES = ["phantom-curvature.png", "phantom-reduced.png", "phantom-smooth.png"]
STUDY_RENDERS = [f"render-{s}-{k}.png" for s in ("linear", "loop", "side-vertex") for k in ("isophotes", "reflection")]


def vertex_property(path, name):
    """One vertex property of a binary little-endian PLY."""
    with open(path, "rb") as f:
        data = f.read()
    header, body = data.split(b"end_header\n", 1)
    fields, count, in_vertex = [], 0, False
    for line in header.decode("ascii").splitlines():
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count, in_vertex = int(words[2]), True
        elif words[:1] == ["element"]:
            in_vertex = False
        elif words[:1] == ["property"] and in_vertex:
            fields.append((words[2], {"float": "<f4", "double": "<f8", "uchar": "u1", "char": "i1", "ushort": "<u2",
                                      "short": "<i2", "int": "<i4", "uint": "<u4"}[words[1]]))
    return np.frombuffer(body, dtype=fields, count=count)[name]


OUTER_SKULL_AXES = np.array([0.69, 0.92, 0.81])  # libcore/phantom.cpp
# The default curvature fit on the 128^3 phantom's outer skull against the
# ellipsoid's own H: bounds with room over what it gives (the test prints it).
RMS_BOUND, WORST_BOUND = 0.06, 0.35


def outer_skull(contour_faces, parts):
    """The vertices of the contour's largest part: the skull's outer surface,
    convex, whose normals face out."""
    largest = np.bincount(parts).argmax()
    return np.unique(np.asarray(contour_faces)[np.asarray(parts) == largest])


def ellipsoid_mean_curvature(points, axes=OUTER_SKULL_AXES):
    """H of the ellipsoid sum (x_i / a_i)^2 = 1 at the points scaled onto it
    along their rays from the centre, outward normals: for the implicit F,
    H = (|g|^2 tr(Hess F) - g.(Hess F)g) / (2 |g|^3)."""
    q = points / np.sqrt(np.sum((points / axes) ** 2, axis=1))[:, None]
    hess = 2 / axes ** 2
    g = q * hess
    g2 = np.sum(g * g, axis=1)
    return (g2 * hess.sum() - np.sum(g * g * hess, axis=1)) / (2 * g2 ** 1.5)


def is_png(path):
    with open(path, "rb") as f:
        return f.read(8) == b"\x89PNG\r\n\x1a\n"


def case_pipeline(tmp):
    folder = os.path.join(tmp, "out")
    report, _ = run_json("pipeline", "-o", folder)  # the README's main job, 128^3
    vdb, ply = os.path.join(folder, "phantom.vdb"), os.path.join(folder, "phantom-contour.ply")
    curved = os.path.join(folder, "phantom-curvature.ply")
    reduced, smooth = os.path.join(folder, "phantom-reduced.ply"), os.path.join(folder, "phantom-smooth.ply")
    study = os.path.join(folder, "phantom-study")
    page = os.path.join(folder, "phantom-report.html")
    expect(report["written"] == [vdb, ply, curved, reduced, smooth, os.path.join(study, "report.md"), page],
           f"written: {report['written']}")
    expect(leftovers(folder, PIPELINE_FILES + PICTURES) == [],
           f"left behind: {leftovers(folder, PIPELINE_FILES + PICTURES)}")
    points, _, faces, parts = check_ply_mesh(ply, report["contour"])
    expect(len(set(parts)) >= 2, f"the skull gives {len(set(parts))} parts, expected 2 or more")
    c = report["curvature"]
    expect(c["vertices"] == report["contour"]["vertices"] and c["fallbacks"]["failed"] == 0, f"curvature: {c}")
    # The skull's outer surface is convex and its density ramps linearly where
    # the contour crosses it: H is positive at every one of its vertices.
    outer = outer_skull(faces, parts)
    h = vertex_property(curved, "mean")[outer]
    expect(h.min() > 0, f"outer skull: H from {h.min()} to {h.max()}, {np.sum(h <= 0)} vertices at or below 0")
    truth = ellipsoid_mean_curvature(np.asarray(points, dtype=float)[outer])
    error = (h - truth) / truth
    rms, worst = float(np.sqrt(np.mean(error ** 2))), float(np.abs(error).max())
    print(f"outer skull mean curvature against the ellipsoid's: RMS relative error {rms:.4f}, largest {worst:.4f}"
          f" ({len(outer)} vertices)")
    expect(rms < RMS_BOUND and worst < WORST_BOUND, f"outer skull H: RMS relative error {rms}, largest {worst}")
    # The pictures, made by Blender (the README's command installs it), and
    # the page that shows them.
    expect(report["pictures"] == "made", f"pictures: {report['pictures']}")
    for name in PICTURES:
        expect(is_png(os.path.join(folder, name)), f"{name} is not a PNG")
    with open(page) as f:
        html = f.read()
    for name in PICTURES + [f"phantom-study/{r}" for r in STUDY_RENDERS] + ["phantom-study/report.md"]:
        expect(f'"{name}"' in html, f"the page does not show {name}")
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
    expect(sorted(os.listdir(study)) == sorted(["report.json", "report.md", "samples.csv", "surface-linear.ply",
                                                "surface-loop.ply", "surface-side-vertex.ply"] + STUDY_RENDERS),
           f"{study}: {sorted(os.listdir(study))}")
    expect(all(is_png(os.path.join(study, r)) for r in STUDY_RENDERS), "a study render is not a PNG")


def case_pipeline_again(tmp):
    folder = os.path.join(tmp, "out")
    run("pipeline", "-o", folder, "--size", "32", "--quiet", "--no-render")
    proc = run("pipeline", "-o", folder, "--size", "32", "--method", "tetra", "--no-render")
    expect("phantom-contour.ply" in proc.stdout, f"summary: {proc.stdout}")
    check_ply_mesh(os.path.join(folder, "phantom-contour.ply"))
    expect(sorted(os.listdir(folder)) == sorted(PIPELINE_FILES), f"folder holds {sorted(os.listdir(folder))}")
    with open(os.path.join(folder, "phantom-report.html")) as f:
        expect("No pictures: --no-render." in f.read(), "the page does not say why it has no pictures")


def case_pipeline_on_a_file(tmp):
    """pipeline sphere.vdb: files named after the input, the input untouched."""
    sphere = data("sphere.vdb")
    before = os.path.getmtime(sphere)
    folder = os.path.join(tmp, "out")
    report, _ = run_json("pipeline", sphere, "-o", folder, "--keep", "5%", "--level", "1", "--no-render")
    expect(report["input"] == sphere and report["contour"]["isovalue"] == 0.0, f"report: {report['contour']}")
    expect(sorted(os.listdir(folder)) == ["sphere-contour.ply", "sphere-curvature.ply", "sphere-reduced.ply",
                                          "sphere-report.html", "sphere-smooth.ply", "sphere-study"],
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
