"""Figures 4.9 to 4.12 as a user makes them: a trivariate function written as
a raw scan, `convert`, `curvature-volume`, then `slice` of the curvature grids
with the diverging map. Checks the values against the exact curvature of the
graph of .4(x^2 + y^2 + z^2) (Figure 4.9) and the written pictures.

Usage: test_cli_curvature_slices.py ISOFORM_BINARY SHARED_DATA_DIR GROUP"""
import math
import os
import struct
import sys

import test_cli as base
from test_cli import expect, run, run_json, leftovers

N, H = 26, 0.08  # the seed's 26^3 grid over [-1, 1]^3


def exact_mean(x, y, z):
    """H of the graph of f = .4 r^2: (2 * .8 / l + .8 / l^3) / 3, l = sqrt(1 + .64 r^2)."""
    l = math.sqrt(1 + 0.64 * (x * x + y * y + z * z))
    return (2 * 0.8 / l + 0.8 / l ** 3) / 3


def make_figure49(tmp):
    raw = os.path.join(tmp, "f.raw")
    values = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                x, y, z = -1 + H * i, -1 + H * j, -1 + H * k
                values.append(1 + 0.4 * (x * x + y * y + z * z))  # + 1: every sample active
    with open(raw, "wb") as f:
        f.write(struct.pack(f"<{len(values)}f", *values))
    vdb = os.path.join(tmp, "figure49.vdb")
    run("convert", raw, "--dims", f"{N},{N},{N}", "--type", "f32", "--spacing", f"{H},{H},{H}",
        "--origin", "-1,-1,-1", "-o", vdb)
    return vdb


def case_figure49_slices(tmp):
    vdb = make_figure49(tmp)
    curv = os.path.join(tmp, "curvature.vdb")
    summary, _ = run_json("curvature-volume", vdb, "-o", curv)
    mean = summary["grids"]["mean"]
    # The largest H is at the grid points nearest the origin (+-0.04 on each
    # axis: 26 points put none at 0), the smallest at the corners.
    centre = exact_mean(0.04, 0.04, 0.04)
    expect(abs(mean["max"] - centre) < 2e-4, f"max H {mean['max']}, exact {centre}")
    expect(abs(mean["min"] - exact_mean(1, 1, 1)) < 2e-4, f"min H {mean['min']}, exact {exact_mean(1, 1, 1)}")
    for quantity in ("mean", "gauss"):
        folder = os.path.join(tmp, quantity)
        sl, _ = run_json("slice", curv, "--grid", quantity, "--map", "diverging", "-o", folder)
        lo, hi = sl["range"]
        expect(abs(lo + hi) < 1e-9 and hi > 0, f"{quantity}: diverging range {sl['range']} not symmetric")
        expect(hi >= summary["grids"][quantity]["max"] - 1e-6 or quantity == "gauss",
               f"{quantity}: range {sl['range']} misses the grid's max")
        for name in ("slice-x.png", "slice-y.png", "slice-z.png", "slice-planes.ply"):
            path = os.path.join(folder, name)
            expect(os.path.isfile(path) and os.path.getsize(path) > 0, f"{path} not written")
        with open(os.path.join(folder, "slice-z.png"), "rb") as f:
            expect(f.read(8) == b"\x89PNG\r\n\x1a\n", f"{quantity}: slice-z.png is not a PNG")


GROUPS = {"figure49": [case_figure49_slices]}

if __name__ == "__main__":
    base.run_groups(GROUPS, sys.argv)
