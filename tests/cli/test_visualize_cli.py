#!/usr/bin/python3
"""The Chapter 2 commands (slice, boxes, stack) run as a program.

usage: test_visualize_cli.py ISOFORM_BINARY SHARED_DATA_DIR GROUP

Shares the runner and the PLY parser of test_cli.py; the volumes are made
here (a raw float file of the seed's three Gaussians, converted with
`isoform convert`) or are the real files of the shared data folder. PNG
headers and text chunks are read here with zlib and struct.
"""
import math
import os
import struct
import sys
import zlib

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_cli as base  # noqa: E402
from test_cli import (CaseFailure, check_one_error_line, data, expect, leftovers,  # noqa: E402
                      parse_ply_header, read_ply_element, run, run_json)

VIRIDIS = [(68, 1, 84), (72, 40, 120), (62, 73, 137), (49, 104, 142), (38, 130, 142),
           (31, 158, 137), (53, 183, 121), (110, 206, 88), (253, 231, 37)]


def viridis(index, levels=256):
    s = index / (levels - 1) * (len(VIRIDIS) - 1)
    i = min(int(s), len(VIRIDIS) - 2)
    t = s - i
    return tuple(int(math.floor((1 - t) * a + t * b + 0.5)) for a, b in zip(VIRIDIS[i], VIRIDIS[i + 1]))


def gaussians(x, y, z):
    """The function of Figures 2.2 and 2.3."""
    a = (x - 10) ** 2 + (y - 10) ** 2 + (z - 10) ** 2
    b = (x - 15) ** 2 + (y - 20) ** 2 + (z - 20) ** 2
    c = (x - 25) ** 2 + (y - 25) ** 2 + (z - 25) ** 2
    return 15 * (math.exp(-0.005 * a) + math.exp(-0.0025 * b) + math.exp(-0.005 * c))


def make_gaussians(tmp):
    """gaussians.vdb: the seed's function at the integers of [0, 39]^3."""
    raw = os.path.join(tmp, "g.raw")
    values = [gaussians(i, j, k) for k in range(40) for j in range(40) for i in range(40)]
    with open(raw, "wb") as f:
        f.write(struct.pack(f"<{len(values)}f", *values))
    vdb = os.path.join(tmp, "gaussians.vdb")
    run("convert", raw, "--dims", "40,40,40", "--type", "f32", "-o", vdb)
    os.remove(raw)
    return vdb


def read_coloured_ply(path):
    """Returns {element name: rows} of a binary PLY with any elements."""
    with open(path, "rb") as f:
        blob = f.read()
    order, elements, offset = parse_ply_header(blob)
    out = {}
    for name, count, properties in elements:
        out[name], offset = read_ply_element(blob, offset, order, count, properties)
        out[name + "_properties"] = [p[0] for p in properties]
    expect(offset == len(blob), f"{path}: {len(blob) - offset} bytes after the last element")
    return out


def read_png(path):
    """Returns (width, height, {text key: value}) from a PNG's chunks."""
    with open(path, "rb") as f:
        blob = f.read()
    expect(blob[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG")
    offset, texts, size = 8, {}, None
    while offset < len(blob):
        (length,) = struct.unpack_from(">I", blob, offset)
        kind = blob[offset + 4:offset + 8]
        body = blob[offset + 8:offset + 8 + length]
        expect(zlib.crc32(kind + body) == struct.unpack_from(">I", blob, offset + 8 + length)[0],
               f"{path}: bad CRC in {kind}")
        if kind == b"IHDR":
            size = struct.unpack(">II", body[:8])
            expect(body[8:10] == b"\x08\x06", f"{path}: not 8-bit RGBA")
        elif kind == b"tEXt":
            key, value = body.split(b"\0", 1)
            texts[key.decode()] = value.decode()
        offset += 12 + length
    expect(size is not None, f"{path}: no IHDR")
    return size[0], size[1], texts


def rectangle_key(vertices, r, view):
    return min(sum(v[a] * view[i] for i, a in enumerate("xyz")) for v in vertices[4 * r:4 * r + 4])


# ---------------------------------------------------------------- slice

SLICE_FILES = ["slice-x.png", "slice-y.png", "slice-z.png", "slice-planes.ply",
               "slice-surfaces.ply", "slice-curves.ply"]


def case_slice_gaussians(tmp):
    vdb = make_gaussians(tmp)
    out = os.path.join(tmp, "slices")
    report, _ = run_json("slice", vdb, "--at", "x=0.25,y=0.5,z=1", "--res", "40", "-o", out)
    expect(sorted(os.listdir(out)) == sorted(SLICE_FILES), f"slices/ holds {sorted(os.listdir(out))}")
    f_min, f_max = report["range"]
    for image in report["images"]:
        w, h, texts = read_png(image["file"])
        expect((w, h) == (image["width"], image["height"]) and h == 40 and w == 40 + 4 + 8,
               f"{image['file']}: {w} x {h}, summary {image}")
        lo, hi = (float(v) for v in texts["isoform range"].split())
        expect(math.isclose(lo, f_min, rel_tol=1e-6) and math.isclose(hi, f_max, rel_tol=1e-6),
               f"PNG range {lo}..{hi}, summary {f_min}..{f_max}")
    planes = read_coloured_ply(os.path.join(out, "slice-planes.ply"))
    expect(planes["vertex_properties"] == ["x", "y", "z", "nx", "ny", "nz", "red", "green", "blue", "alpha"],
           f"plane vertex properties {planes['vertex_properties']}")
    expect(len(planes["vertex"]) == 3 * 40 * 40 + 8 and len(planes["edge"]) == 12,
           f"{len(planes['vertex'])} vertices, {len(planes['edge'])} edges")
    expect(len(planes["face"]) == 3 * 2 * 39 * 39, f"{len(planes['face'])} triangles")
    # The z slice (the third block of vertices) lies at z = 39: at its grid
    # points the colour is the seed's index of f there, up to one level of
    # float rounding.
    z_block = planes["vertex"][2 * 1600:3 * 1600]
    checked = 0
    for v in z_block[::37]:
        expect(v["z"] == 39.0, f"z slice vertex at z = {v['z']}")
        f = gaussians(v["x"], v["y"], 39)
        c = math.ceil((f - f_min) / (f_max - f_min) * 255 - 1e-9 * 255)
        colour = (v["red"], v["green"], v["blue"])
        expect(colour in [viridis(max(0, min(255, c + d))) for d in (-1, 0, 1)],
               f"colour {colour} at ({v['x']}, {v['y']}, 39), f = {f}, index {c}: {viridis(c)}")
        checked += 1
    expect(checked > 30, "too few vertices checked")
    curves = read_coloured_ply(os.path.join(out, "slice-curves.ply"))
    expect(len(curves["face"]) == 0 and len(curves["edge"]) == 3 * 2 * 40 * 39,
           f"curves: {len(curves['face'])} faces, {len(curves['edge'])} edges")
    surfaces = read_coloured_ply(os.path.join(out, "slice-surfaces.ply"))
    top = max(v["z"] for v in surfaces["vertex"][2 * 1600:3 * 1600])
    expect(39 < top <= 39 + 0.25 * 39 + 1e-3, f"the z graph reaches z = {top}")


def case_slice_world_and_text(tmp):
    vdb = make_gaussians(tmp)
    out = os.path.join(tmp, "w")
    report, _ = run_json("slice", vdb, "--world", "--at", "x=10,z=20", "--res", "16", "--map",
                         "diverging", "-o", out)
    expect(report["position"] == [10, 19.5, 20] and report["position_is_world"],
           f"position {report['position']}")
    expect(report["range"][0] == -report["range"][1], f"diverging range {report['range']}")
    proc = run("slice", vdb, "--res", "8", "--map", "green-white", "-o", out)
    expect("wrote" in proc.stdout and "green-white" in proc.stdout, f"summary: {proc.stdout}")


def case_slice_outside_domain(tmp):
    vdb = make_gaussians(tmp)
    out = os.path.join(tmp, "slices")
    for at, world in (("x=1.5", []), ("y=-0.1", []), ("z=40", ["--world"])):
        proc = run("slice", vdb, "--at", at, *world, "-o", out, code=1)
        check_one_error_line(proc, ["gaussians.vdb", "outside the domain"])
        expect(not os.path.exists(out), f"--at {at}: the output folder was made")


# ---------------------------------------------------------------- boxes

def case_boxes_figure_22(tmp):
    vdb = make_gaussians(tmp)
    out = os.path.join(tmp, "boxes.ply")
    report, _ = run_json("boxes", vdb, "--q", "5,5,5", "--gap", "1", "-o", out)
    expect(report["subvolumes"] == 125 and report["mesh"]["triangles"] == 1500, f"{report}")
    ply = read_coloured_ply(out)
    expect(len(ply["vertex"]) == 125 * 24, f"{len(ply['vertex'])} vertices")
    expect(sorted({f["part"] for f in ply["face"]}) == list(range(125)), "parts are not the 125 boxes")
    # dx = 39 / 9, x_r = 2 r dx: corners at 0, 13/3, 26/3, 13, ..., 39.
    expected = sorted({round(2 * r * 39 / 9 + e * 39 / 9, 3) for r in range(5) for e in (0, 1)})
    for axis in "xyz":
        seen = sorted({round(v[axis], 3) for v in ply["vertex"]})
        expect(seen == expected, f"{axis} corners {seen}, expected {expected}")
    white = [v for v in ply["vertex"] if (v["red"], v["green"], v["blue"]) == (255, 255, 255)]
    green = [v for v in ply["vertex"] if (v["red"], v["green"], v["blue"]) == (0, 128, 0)]
    expect(white and green, "green-white map: no corner reaches green or white")
    expect(all(v["alpha"] == 255 for v in ply["vertex"]), "boxes are not opaque")


def case_boxes_spherical_and_lines(tmp):
    vdb = os.path.join(tmp, "ball.vdb")
    raw = os.path.join(tmp, "ball.raw")
    values = [math.cos(2 * math.sqrt(((i - 20) / 20) ** 2 + ((j - 20) / 20) ** 2 + ((k - 20) / 20) ** 2))
              for k in range(41) for j in range(41) for i in range(41)]
    with open(raw, "wb") as f:
        f.write(struct.pack(f"<{len(values)}f", *values))
    run("convert", raw, "--dims", "41,41,41", "--type", "f32", "--spacing", "0.05,0.05,0.05",
        "--origin", "-1,-1,-1", "-o", vdb)
    out = os.path.join(tmp, "ball.ply")
    report, _ = run_json("boxes", vdb, "--domain", "spherical", "--q", "5", "--gap", "2",
                         "--face-cells", "4", "--centroid-lines", "-o", out)
    ply = read_coloured_ply(out)
    radii = [math.sqrt(v["x"] ** 2 + v["y"] ** 2 + v["z"] ** 2) for v in ply["vertex"]]
    expect(abs(max(radii) - 1) < 1e-5, f"largest radius {max(radii)}, expected 1 (u = 1)")
    expect(len(ply["edge"]) == 3 * 4 * 25, f"{len(ply['edge'])} centroid lines, expected 300")
    proc = run("boxes", vdb, "--domain", "spherical", "--uvw-max", "3,3.14159,3.14159", "-o", out + "2.ply",
               code=1)
    check_one_error_line(proc, ["ball.vdb", "outside the domain"])


def case_boxes_bad_q(tmp):
    vdb = make_gaussians(tmp)
    for q in ("0", "5,0,5"):
        proc = run("boxes", vdb, "--q", q, "-o", os.path.join(tmp, "b.ply"), code=1)
        check_one_error_line(proc, ["gaussians.vdb", "q = 0"])
    proc = run("boxes", vdb, "--gap", "-1", "-o", os.path.join(tmp, "b.ply"), code=1)
    check_one_error_line(proc, ["gaussians.vdb", "gap"])
    proc = run("boxes", vdb, "--q", "five", "-o", os.path.join(tmp, "b.ply"), code=1)
    check_one_error_line(proc, ["--q", "five"])
    expect(leftovers(tmp, ["gaussians.vdb"]) == [], f"left behind {leftovers(tmp, ['gaussians.vdb'])}")


# ---------------------------------------------------------------- stack

def case_stack_order(tmp):
    vdb = make_gaussians(tmp)
    for view in ((-1, -1, -1), (1, 2, 3), (0, 0, -1)):
        out = os.path.join(tmp, "stack.ply")
        text = ",".join(str(v) for v in view)
        report, _ = run_json("stack", vdb, "--n", "8", "--t", "0.5", "--view", text, "-o", out)
        expect(report["rectangles"] == 3 * 512 + 3 * 64, f"{report['rectangles']} rectangles")
        ply = read_coloured_ply(out)
        vertices = ply["vertex"]
        expect(len(vertices) == 4 * 1728 and len(ply["face"]) == 2 * 1728, "counts")
        keys = [rectangle_key(vertices, r, view) for r in range(1728)]
        bad = sum(1 for a, b in zip(keys, keys[1:]) if b > a + 1e-4)
        expect(bad == 0, f"view {view}: {bad} rectangles nearer than the one after them")
        expect(all(v["alpha"] == 128 for v in vertices), "alpha is not 1 - t = 0.5")
    proc = run("stack", vdb, "--t", "2", "-o", os.path.join(tmp, "s.ply"), code=1)
    check_one_error_line(proc, ["gaussians.vdb", "transparency"])
    proc = run("stack", vdb, "--view", "0,0,0", "-o", os.path.join(tmp, "s.ply"), code=1)
    check_one_error_line(proc, ["gaussians.vdb", "view"])


# ---------------------------------------------------------------- help, bad input, real data

HELP_OPTIONS = {
    "slice": ["--grid", "--at", "--world", "--res", "--map", "--range", "--levels", "--height",
              "--no-bar", "--output", "--json"],
    "boxes": ["--grid", "--q", "--gap", "--face-cells", "--centroid-lines", "--domain", "--uvw-min",
              "--uvw-max", "--centre", "--map", "--output", "--json"],
    "stack": ["--grid", "--n", "--t", "--view", "--map", "--output", "--json"],
}


def case_help(tmp):
    top = run("--help").stdout
    for command, options in HELP_OPTIONS.items():
        expect(command in top, f"isoform --help does not list {command}")
        text = run(command, "--help").stdout
        missing = [o for o in options if o not in text]
        expect(not missing, f"isoform {command} --help does not name {missing}")
    proc = run("slice", "in.vdb", "-o", "x", "--map", "rainbow", code=2)
    expect(proc.stderr.strip(), "no usage message for an unknown map")


def case_bad_input(tmp):
    vdb = make_gaussians(tmp)
    for command, extra in (("slice", ["-o", os.path.join(tmp, "s")]),
                           ("boxes", ["-o", os.path.join(tmp, "b.ply")]),
                           ("stack", ["-o", os.path.join(tmp, "t.ply")])):
        proc = run(command, vdb, "--grid", "nosuch", *extra, code=1)
        check_one_error_line(proc, ["gaussians.vdb", "nosuch", "gaussians"])
        proc = run(command, os.path.join(tmp, "missing.vdb"), *extra, code=1)
        check_one_error_line(proc, ["missing.vdb"])
    proc = run("slice", vdb, "--range", "3,1", "-o", os.path.join(tmp, "s"), code=1)
    check_one_error_line(proc, ["gaussians.vdb", "colour range"])
    proc = run("boxes", vdb, "--levels", "1", "-o", os.path.join(tmp, "b.ply"), code=1)
    check_one_error_line(proc, ["gaussians.vdb", "levels"])
    proc = run("slice", vdb, "--at", "x=abc", "-o", os.path.join(tmp, "s"), code=1)
    check_one_error_line(proc, ["--at", "x=abc"])
    proc = run("boxes", vdb, "-o", vdb, code=1)
    check_one_error_line(proc, ["gaussians.vdb"])
    proc = run("stack", vdb, "-o", os.path.join(tmp, "t.stl"), code=1)
    check_one_error_line(proc, ["t.stl"])
    expect(leftovers(tmp, ["gaussians.vdb"]) == [], f"left behind {leftovers(tmp, ['gaussians.vdb'])}")


def case_smoke(tmp):
    out = os.path.join(tmp, "smoke")
    report, _ = run_json("slice", data("smoke.vdb"), "--at", "x=0.3,y=0.5,z=0.7", "--res", "64", "-o", out)
    expect(report["grid"] == "density" and report["range"][1] > report["range"][0], f"{report}")
    expect(sorted(os.listdir(out)) == sorted(SLICE_FILES), f"{os.listdir(out)}")
    # smoke's index box is 111 x 222 x 112 voxels: the x slice (y by z) is 64 wide, 32 high.
    w, h, _ = read_png(os.path.join(out, "slice-x.png"))
    expect(h == 32 and w > 64, f"slice-x.png is {w} x {h}")
    boxes = os.path.join(tmp, "smoke-boxes.ply")
    report, _ = run_json("boxes", data("smoke.vdb"), "--q", "4,8,4", "--gap", "0.5", "-o", boxes)
    expect(report["mesh"]["triangles"] == 128 * 12, f"{report['mesh']}")
    g = run_json("info", data("smoke.vdb"))[0]["grids"][0]
    t = g["transform"]
    want_lo = [t[a][a] * g["bbox_min"][a] + t[a][3] for a in range(3)]
    want_hi = [t[a][a] * g["bbox_max"][a] + t[a][3] for a in range(3)]
    lo, hi = report["mesh"]["bbox_min"], report["mesh"]["bbox_max"]
    expect(all(abs(a - b) < 1e-3 for a, b in zip(lo + hi, want_lo + want_hi)),
           f"boxes span {lo}..{hi}, expected the active box {want_lo}..{want_hi} in world units")
    stack = os.path.join(tmp, "smoke-stack.ply")
    report, _ = run_json("stack", data("smoke.vdb"), "--n", "6", "--t", "0.8", "-o", stack)
    expect(report["rectangles"] == 3 * 216 + 3 * 36, f"{report['rectangles']}")


def case_headsq(tmp):
    vdb = os.path.join(tmp, "head.vdb")
    run("convert", data("headsq_64x64x93_u16le.raw"), "--dims", "64,64,93", "--type", "u16",
        "--spacing", "3.2,3.2,1.5", "-o", vdb)
    out = os.path.join(tmp, "head")
    report, _ = run_json("slice", vdb, "--res", "100", "--range", "0,3926", "--map", "green-white",
                         "-o", out)
    expect(report["range"] == [0, 3926], f"range {report['range']}")
    # The scan's active box is not square: the longer side has 100 samples.
    w, h, _ = read_png(os.path.join(out, "slice-z.png"))
    expect(max(w - 4 - 8, h) == 100, f"slice-z.png {w} x {h}")
    report, _ = run_json("boxes", vdb, "--q", "3", "--gap", "1", "-o", os.path.join(tmp, "hb.ply"))
    expect(report["mesh"]["triangles"] == 27 * 12, f"{report}")


GROUPS = {
    "vis_slice": [case_slice_gaussians, case_slice_world_and_text, case_slice_outside_domain],
    "vis_boxes": [case_boxes_figure_22, case_boxes_spherical_and_lines, case_boxes_bad_q],
    "vis_stack": [case_stack_order, case_bad_input, case_help],
    "vis_realdata": [case_smoke, case_headsq],
}


if __name__ == "__main__":
    base.run_groups(GROUPS, sys.argv)
