"""`isoform compare`, run as a program: the study's files exist and parse,
their numbers are the ones the geometry implies (the flat triangles
interpolate the vertices and are not tangent continuous; Loop is tangent
continuous and does not interpolate), and bad input fails with one line that
names the file and leaves no study behind. Shares test_cli.py's helpers.

Usage: test_cli_compare.py ISOFORM_BINARY SHARED_DATA_DIR GROUP"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys

import test_cli as base
from test_cli import expect, run, run_json, data, leftovers, expect_failure

STUDY_FILES = ["report.json", "samples.csv", "report.md", "surface-linear.ply", "surface-loop.ply",
               "surface-side-vertex.ply"]


def icosphere(path, levels, radius=2.0, centre=(0.5, -0.25, 1.0)):
    """Writes an ASCII PLY of a subdivided icosahedron on a sphere; returns its triangle count."""
    g = (1 + math.sqrt(5)) / 2
    pts = [(-1, g, 0), (1, g, 0), (-1, -g, 0), (1, -g, 0), (0, -1, g), (0, 1, g), (0, -1, -g), (0, 1, -g),
           (g, 0, -1), (g, 0, 1), (-g, 0, -1), (-g, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
             (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    pts = [tuple(c / math.sqrt(1 + g * g) for c in p) for p in pts]
    for _ in range(levels):
        mid, new = {}, []

        def m(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                p = [(pts[a][i] + pts[b][i]) / 2 for i in range(3)]
                n = math.sqrt(sum(c * c for c in p))
                pts.append(tuple(c / n for c in p))
                mid[key] = len(pts) - 1
            return mid[key]
        for a, b, c in faces:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            new += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new
    with open(path, "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(pts)}\nproperty float x\nproperty float y\n"
                f"property float z\nelement face {len(faces)}\nproperty list uchar int vertex_indices\n"
                "end_header\n")
        for p in pts:
            f.write(" ".join(repr(centre[i] + radius * p[i]) for i in range(3)) + "\n")
        for t in faces:
            f.write(f"3 {t[0]} {t[1]} {t[2]}\n")
    return len(faces)


def read_study(folder):
    for name in STUDY_FILES:
        expect(os.path.isfile(os.path.join(folder, name)), f"{folder}: no {name} ({sorted(os.listdir(folder))})")
    with open(os.path.join(folder, "report.json")) as f:
        report = json.load(f)
    with open(os.path.join(folder, "samples.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(folder, "report.md")) as f:
        md = f.read()
    return report, rows, md


def surface(report, name):
    found = [s for s in report["surfaces"] if s["name"] == name]
    expect(len(found) == 1, f"report has surfaces {[s['name'] for s in report['surfaces']]}")
    return found[0]


def case_sphere_reference(tmp):
    mesh = os.path.join(tmp, "ico.ply")
    triangles = icosphere(mesh, 2)
    out = os.path.join(tmp, "study")
    summary, _ = run_json("compare", mesh, "--reference", "sphere", "--level", "4", "--no-render", "-o", out)
    report, rows, md = read_study(out)
    expect(report["base_triangles"] == triangles == 320, f"base triangles {report['base_triangles']}")
    expect(report["level"] == 4 and report["samples_per_triangle"] == 15, f"{report['level']}")
    # The fitted sphere is the one the vertices lie on.
    desc = report["reference"]["description"]
    expect("radius 2" in desc or "radius 1.99999" in desc, f"fitted reference: {desc}")
    flat, loop = surface(report, "linear"), surface(report, "loop")
    expect(flat["samples"] == loop["samples"] == 320 * 15, f"samples {flat['samples']}")
    expect(flat["data_point_error"]["max"] == 0.0, f"flat data-point error {flat['data_point_error']}")
    expect(0.01 < flat["deviation"]["max"] < 0.05, f"flat deviation {flat['deviation']}")
    expect(loop["data_point_error"]["max"] > 1e-3, f"Loop interpolates? {loop['data_point_error']}")
    expect(loop["normal_gap_radians"]["max"] < 1e-6, f"Loop normal gap {loop['normal_gap_radians']}")
    expect(flat["normal_gap_radians"]["max"] > 0.05, f"flat normal gap {flat['normal_gap_radians']}")
    expect(loop["position_gap"]["max"] < 1e-9, f"Loop position gap {loop['position_gap']}")
    sv = surface(report, "side-vertex")
    expect(sv["data_point_error"]["max"] < 1e-6, f"side-vertex data-point error {sv['data_point_error']}")
    expect(sv["normal_gap_radians"]["max"] < 1e-6, f"side-vertex normal gap {sv['normal_gap_radians']}")
    h = loop["mean_curvature"]["p50"]
    expect(abs(h * 2.0 - 1) < 0.05, f"Loop median H {h}, sphere 1/r = 0.5")
    expect(flat["tessellation_triangles"] == loop["tessellation_triangles"] == 320 * 16, f"{flat['tessellation_triangles']}")
    expect(len(rows) == 320 * 15, f"samples.csv has {len(rows)} rows")
    expect(set(rows[0]) >= {"triangle", "u", "v", "loop_x", "loop_deviation", "loop_mean", "linear_gauss"},
           f"samples.csv columns {list(rows[0])}")
    expect("| measure | linear | loop | side-vertex |" in md and "normal gap" in md, f"report.md:\n{md[:600]}")
    points, normals, faces, _ = base.read_ply(os.path.join(out, "surface-loop.ply"))
    expect(len(faces) == 320 * 16, f"surface-loop.ply has {len(faces)} triangles")
    expect(all(math.isfinite(c) for p in points for c in p), "NaN in surface-loop.ply")
    expect(summary["pictures"]["renders"] == "skipped: --no-render", f"{summary['pictures']}")
    # Plots need the system's matplotlib; when it is there they must be made.
    has_mpl = subprocess.run(["/usr/bin/python3", "-c", "import matplotlib"], capture_output=True).returncode == 0
    if has_mpl:
        expect(summary["pictures"]["plots"] == "made", f"{summary['pictures']}")
        for png in ("curvature-histograms.png", "deviation.png", "metrics.png"):
            with open(os.path.join(out, png), "rb") as f:
                expect(f.read(8) == b"\x89PNG\r\n\x1a\n", f"{png} is not a PNG")


def case_torus_given_and_no_reference(tmp):
    mesh = os.path.join(tmp, "ico.ply")
    icosphere(mesh, 1)
    out = os.path.join(tmp, "plain")
    run("compare", mesh, "--level", "2", "--no-render", "--no-plots", "--quiet", "-o", out)
    report, rows, _ = read_study(out)
    expect(report["reference"]["kind"] == "none", f"{report['reference']}")
    expect(surface(report, "loop")["deviation"]["count"] == 0, "deviation without a reference")
    expect(all(r["loop_deviation"] == "nan" for r in rows), "deviation values without a reference")
    out2 = os.path.join(tmp, "torus")
    run("compare", mesh, "--reference", "torus", "--centre", "0,0,0", "--radius", "3", "--minor-radius", "1",
        "--level", "2", "--no-render", "--no-plots", "--quiet", "-o", out2)
    report, _, _ = read_study(out2)
    expect("radii 3 and 1" in report["reference"]["description"], f"{report['reference']}")


def case_volume_reference(tmp):
    """sphere.vdb's contour against sphere.vdb itself, in voxels: the flat
    contour sits on the trilinear contour at its vertices; Loop pulls inside."""
    mesh = os.path.join(tmp, "sphere.ply")
    run("contour", data("sphere.vdb"), "-o", mesh, "--quiet")
    out = os.path.join(tmp, "study")
    summary, _ = run_json("compare", mesh, "--reference", data("sphere.vdb"), "--level", "2",
                          "--isolation", "3", "--no-render", "--no-plots", "--quiet", "-o", out)
    report, _, _ = read_study(out)
    expect(report["reference"]["kind"] == "volume" and report["reference"]["deviation_unit"] == "voxels",
           f"{report['reference']}")
    flat, loop = surface(report, "linear"), surface(report, "loop")
    expect(flat["deviation"]["rms"] < 0.05, f"flat contour deviation {flat['deviation']} voxels")
    expect(loop["deviation"]["rms"] > flat["deviation"]["rms"], f"Loop {loop['deviation']} vs flat {flat['deviation']}")
    expect(loop["deviation"]["max"] < 1.0, f"Loop deviation {loop['deviation']} voxels")


def case_bad_input(tmp):
    out = os.path.join(tmp, "study")
    expect_failure(tmp, ["compare", os.path.join(tmp, "missing.ply"), "--no-render", "-o", out], ["missing.ply"], [])
    mesh = os.path.join(tmp, "ico.ply")
    icosphere(mesh, 1)
    expect_failure(tmp, ["compare", mesh, "--reference", os.path.join(tmp, "nothere.vdb"), "--no-render", "-o", out],
                   ["nothere.vdb"], ["ico.ply"])
    bad = os.path.join(tmp, "bad.ply")
    with open(bad, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
    expect_failure(tmp, ["compare", bad, "--no-render", "-o", out], ["bad.ply"], ["ico.ply", "bad.ply"])
    run("compare", mesh, "--reference", "torus", "--radius", "3", "--no-render", "-o", out, code=1)
    expect(leftovers(tmp, ["ico.ply", "bad.ply"]) == [], f"left {leftovers(tmp, ['ico.ply', 'bad.ply'])}")
    blocker = os.path.join(tmp, "file")
    with open(blocker, "w") as f:
        f.write("x")
    expect_failure(tmp, ["compare", mesh, "--no-render", "-o", blocker], ["file"], ["ico.ply", "bad.ply", "file"])
    proc = run("compare", "--help")
    for option in ("--reference", "--iso", "--level", "--no-render", "--output"):
        expect(option in proc.stdout, f"compare --help does not mention {option}")


def case_render_small(tmp):
    """The Blender step renders isophotes and reflection lines of both surfaces."""
    if not shutil.which("blender"):
        print("SKIP blender not installed")
        return
    mesh = os.path.join(tmp, "ico.ply")
    icosphere(mesh, 1)
    out = os.path.join(tmp, "study")
    summary, _ = run_json("compare", mesh, "--reference", "sphere", "--level", "3", "--no-plots", "--quiet", "-o", out)
    expect(summary["pictures"]["renders"] == "made", f"{summary['pictures']}")
    for name in ("linear", "loop", "side-vertex"):
        for kind in ("isophotes", "reflection"):
            png = os.path.join(out, f"render-{name}-{kind}.png")
            with open(png, "rb") as f:
                expect(f.read(8) == b"\x89PNG\r\n\x1a\n", f"{png} is not a PNG")


GROUPS = {
    "compare_files": [case_sphere_reference, case_torus_given_and_no_reference],
    "compare_volume": [case_volume_reference],
    "compare_bad_input": [case_bad_input],
    "compare_render": [case_render_small],
}

if __name__ == "__main__":
    base.run_groups(GROUPS, sys.argv)
