"""The `isoform curvature` command and `contour --curvature`, run as a
program: PLY vertex properties, plausible values on real files, colours,
the JSON summary, and bad input. Shares test_cli.py's helpers.

Usage: test_cli_curvature.py ISOFORM_BINARY SHARED_DATA_DIR GROUP"""
import math
import os
import sys

import test_cli as base
from test_cli import expect, run, run_json, data, leftovers, expect_failure

CURVATURE_PROPS = ["x", "y", "z", "nx", "ny", "nz", "k1", "k2", "mean", "gauss", "absolute",
                   "d1x", "d1y", "d1z", "d2x", "d2y", "d2z", "curvature_flags",
                   "red", "green", "blue", "alpha"]


def read_curvature_ply(path):
    """Returns (vertex rows, face rows) of a curvature PLY, checking its header."""
    with open(path, "rb") as f:
        blob = f.read()
    order, elements, offset = base.parse_ply_header(blob)
    expect([e[0] for e in elements] == ["vertex", "face"], f"{path}: elements {elements}")
    props = [p[0] for p in elements[0][2]]
    expect(props == CURVATURE_PROPS, f"{path}: vertex properties {props}")
    vertices, offset = base.read_ply_element(blob, offset, order, elements[0][1], elements[0][2])
    faces, offset = base.read_ply_element(blob, offset, order, elements[1][1], elements[1][2])
    expect(offset == len(blob), f"{path}: {len(blob) - offset} bytes after the faces")
    return vertices, faces


def median(values):
    s = sorted(values)
    return s[len(s) // 2]


def check_rows(path, rows):
    for r in rows:
        for q in ("k1", "k2", "mean", "gauss", "absolute"):
            expect(math.isfinite(r[q]), f"{path}: {q} is not finite")
        expect(r["k1"] >= r["k2"] - 1e-6, f"{path}: k1 < k2")
        expect(abs(r["mean"] - 0.5 * (r["k1"] + r["k2"])) < 1e-4 * (1 + abs(r["mean"])), f"{path}: H != mean")
        d1 = (r["d1x"], r["d1y"], r["d1z"])
        expect(abs(math.sqrt(sum(c * c for c in d1)) - 1) < 1e-3, f"{path}: d1 not unit")


def case_sphere_contour_curvature(tmp):
    """The level-set sphere of radius ~3 (sphere.vdb): H near 1/r, K near 1/r^2."""
    out = os.path.join(tmp, "sphere.ply")
    summary, _ = run_json("contour", data("sphere.vdb"), "--curvature", "-o", out)
    rows, _ = read_curvature_ply(out)
    check_rows(out, rows)
    radius = median([math.sqrt(r["x"] ** 2 + r["y"] ** 2 + r["z"] ** 2) for r in rows])
    h = median([r["mean"] for r in rows])
    k = median([r["gauss"] for r in rows])
    expect(abs(h * radius - 1) < 0.03, f"median H {h}, 1/r = {1 / radius}")
    expect(abs(k * radius * radius - 1) < 0.06, f"median K {k}, 1/r^2 = {1 / radius ** 2}")
    c = summary["curvature"]
    expect(c["method"] == "quartic" and c["vertices"] == len(rows), f"{c}")
    expect(abs(c["mean"]["p50"] - h) < 1e-3, f"summary median H {c['mean']['p50']} vs file {h}")
    expect(c["fallbacks"]["failed"] == 0 and c["fallbacks"]["isolated"] == 0, f"{c['fallbacks']}")
    expect(c["colors"]["quantity"] == "mean" and c["colors"]["min"] < 0 < c["colors"]["max"], f"{c['colors']}")


def case_curvature_command(tmp):
    """`isoform curvature` on a contour of the CT head (bone): convex skull
    vertices colour red, and the seed method is available by name."""
    vdb = os.path.join(tmp, "head.vdb")
    run("convert", data("headsq_64x64x93_u16le.raw"), "--dims", "64,64,93", "--type", "u16",
        "--spacing", "3.2,3.2,1.5", "-o", vdb)
    mesh = os.path.join(tmp, "bone.ply")
    run("contour", vdb, "--iso", "1150.5", "-o", mesh)
    out = os.path.join(tmp, "curved.ply")
    summary, _ = run_json("curvature", mesh, "-o", out)
    rows, faces = read_curvature_ply(out)
    check_rows(out, rows)
    expect(summary["curvature"]["vertices"] == len(rows), f"{summary}")
    # Most of a skull is convex seen from outside: H > 0 at most vertices.
    positive = sum(1 for r in rows if r["mean"] > 0) / len(rows)
    expect(positive > 0.5, f"only {positive:.2f} of the skull's vertices have H > 0")
    # The diverging map: strongly positive H is red, strongly negative blue.
    lo, hi = summary["curvature"]["colors"]["min"], summary["curvature"]["colors"]["max"]
    reds = [r for r in rows if r["mean"] > 0.8 * hi]
    blues = [r for r in rows if r["mean"] < 0.8 * lo]
    expect(reds and all(r["red"] > r["blue"] for r in reds), "high H is not red")
    expect(blues and all(r["blue"] > r["red"] for r in blues), "low H is not blue")
    seed_out = os.path.join(tmp, "seed.ply")
    seed, _ = run_json("curvature", mesh, "--method", "seed", "--color-by", "absolute", "-o", seed_out)
    expect(seed["curvature"]["method"] == "seed", f"{seed['curvature']['method']}")
    expect(seed["curvature"]["colors"]["quantity"] == "absolute", f"{seed['curvature']['colors']}")
    expect(sorted(leftovers(tmp, [])) == sorted(["head.vdb", "bone.ply", "curved.ply", "seed.ply"]),
           f"left {leftovers(tmp, [])}")


def case_curvature_bad_input(tmp):
    mesh = os.path.join(tmp, "empty.ply")
    with open(mesh, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n"
                "0 0 0\n1 0 0\n0 1 0\n")
    expect_failure(tmp, ["curvature", mesh, "-o", os.path.join(tmp, "out.ply")], ["empty.ply", "no triangles"],
                   ["empty.ply"])
    expect_failure(tmp, ["curvature", os.path.join(tmp, "missing.ply"), "-o", os.path.join(tmp, "out.ply")],
                   ["missing.ply"], ["empty.ply"])
    expect_failure(tmp, ["curvature", mesh, "-o", mesh], ["empty.ply"], ["empty.ply"])
    expect_failure(tmp, ["contour", data("sphere.vdb"), "--curvature", "-o", os.path.join(tmp, "s.stl")],
                   [".stl"], ["empty.ply"])


GROUPS = {
    "curvature": [case_sphere_contour_curvature, case_curvature_command, case_curvature_bad_input],
}


if __name__ == "__main__":
    base.run_groups(GROUPS, sys.argv)
