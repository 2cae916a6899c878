#!/usr/bin/python3
"""The isoform command run as a program, the way a user runs it.

usage: test_cli.py ISOFORM_BINARY SHARED_DATA_DIR GROUP

Each group is one CTest test. Every case runs in its own temporary folder,
and a group runs all its cases and reports each, so one run shows every
failure. Mesh files are parsed here, independently of the library's readers,
so a bug in the writer cannot hide behind the matching bug in a reader.
"""
import gzip
import hashlib
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import traceback
from collections import Counter

BINARY = None
DATA = None
# Generous: the real-data contours take seconds; a hang must still end.
RUN_TIMEOUT_SECONDS = 300


class CaseFailure(Exception):
    pass


def expect(condition, message):
    if not condition:
        raise CaseFailure(message)


def data(name):
    path = os.path.join(DATA, name)
    expect(os.path.isfile(path), f"missing shared test data {path}")
    return path


def run(*args, code=0):
    """Runs isoform with args; checks its exit code and returns the process."""
    proc = subprocess.run([BINARY, *args], capture_output=True, text=True,
                          timeout=RUN_TIMEOUT_SECONDS)
    expect(proc.returncode == code,
           f"isoform {' '.join(args)}: exit {proc.returncode}, expected {code}\n"
           f"stdout: {proc.stdout[-2000:]}\nstderr: {proc.stderr[-2000:]}")
    return proc


def run_json(*args):
    proc = run(*args, "--json")
    try:
        return json.loads(proc.stdout), proc
    except json.JSONDecodeError as error:
        raise CaseFailure(f"--json output does not parse ({error}): {proc.stdout[:500]}")


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def close_to(a, b, tolerance):
    return abs(a - b) <= tolerance


# ---------------------------------------------------------------- mesh files

PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
             "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I",
             "uint32": "I", "float": "f", "float32": "f", "double": "d", "float64": "d"}


def parse_ply_header(blob):
    end = blob.find(b"end_header\n")
    expect(blob.startswith(b"ply\n") and end > 0, "not a PLY file (no ply / end_header)")
    lines = blob[:end].decode("ascii").splitlines()
    fmt = None
    elements = []  # [name, count, [(name, kind, types)]]
    for line in lines[1:]:
        words = line.split()
        if not words or words[0] in ("comment", "obj_info"):
            continue
        if words[0] == "format":
            fmt = words[1]
        elif words[0] == "element":
            elements.append([words[1], int(words[2]), []])
        elif words[0] == "property" and words[1] == "list":
            elements[-1][2].append((words[4], "list", (words[2], words[3])))
        elif words[0] == "property":
            elements[-1][2].append((words[2], "scalar", words[1]))
    expect(fmt in ("binary_little_endian", "binary_big_endian"),
           f"PLY format {fmt}, expected binary")
    return ("<" if fmt == "binary_little_endian" else ">"), elements, end + len(b"end_header\n")


def read_ply_element(blob, offset, order, count, properties):
    """Returns (rows, new offset); a row is a dict from property name to value."""
    if all(kind == "scalar" for _, kind, _ in properties):
        row = struct.Struct(order + "".join(PLY_TYPES[t] for _, _, t in properties))
        end = offset + row.size * count
        expect(end <= len(blob), "PLY body shorter than its header declares")
        names = [name for name, _, _ in properties]
        rows = [dict(zip(names, values)) for values in row.iter_unpack(blob[offset:end])]
        return rows, end
    rows = read_triangle_rows(blob, offset, order, count, properties)
    if rows is not None:
        return rows
    rows = []
    for _ in range(count):
        row = {}
        for name, kind, types in properties:
            if kind == "scalar":
                (row[name],), offset = unpack_at(blob, offset, order + PLY_TYPES[types])
            else:
                (n,), offset = unpack_at(blob, offset, order + PLY_TYPES[types[0]])
                row[name], offset = unpack_at(blob, offset, order + PLY_TYPES[types[1]] * n)
        rows.append(row)
    return rows, offset


def read_triangle_rows(blob, offset, order, count, properties):
    """Fast path for the usual face element: one list property whose every
    count is 3. Returns (rows, new offset), or None to parse row by row."""
    fmt = order
    for _, kind, types in properties:
        fmt += PLY_TYPES[types[0]] + PLY_TYPES[types[1]] * 3 if kind == "list" else PLY_TYPES[types]
    if [kind for _, kind, _ in properties].count("list") != 1:
        return None
    row = struct.Struct(fmt)
    end = offset + row.size * count
    if end > len(blob):
        return None
    rows = []
    for values in row.iter_unpack(blob[offset:end]):
        parsed, i = {}, 0
        for name, kind, _ in properties:
            if kind == "list":
                if values[i] != 3:
                    return None
                parsed[name], i = values[i + 1:i + 4], i + 4
            else:
                parsed[name], i = values[i], i + 1
        rows.append(parsed)
    return rows, end


def unpack_at(blob, offset, fmt):
    """Returns (values, offset after them)."""
    expect(offset + struct.calcsize(fmt) <= len(blob), "PLY body shorter than its header declares")
    return struct.unpack_from(fmt, blob, offset), offset + struct.calcsize(fmt)


def read_ply(path):
    """Checks the header the README promises and returns (points, normals, faces, parts)."""
    with open(path, "rb") as f:
        blob = f.read()
    order, elements, offset = parse_ply_header(blob)
    names = [e[0] for e in elements]
    expect(names == ["vertex", "face"], f"PLY elements {names}, expected vertex and face")
    vertex_props = [p[0] for p in elements[0][2]]
    expect(vertex_props == ["x", "y", "z", "nx", "ny", "nz"],
           f"PLY vertex properties {vertex_props}, expected x y z nx ny nz")
    face_props = [(p[0], p[1]) for p in elements[1][2]]
    expect(face_props == [("vertex_indices", "list"), ("part", "scalar")],
           f"PLY face properties {face_props}, expected vertex_indices (list) and part")
    vertices, offset = read_ply_element(blob, offset, order, elements[0][1], elements[0][2])
    faces, offset = read_ply_element(blob, offset, order, elements[1][1], elements[1][2])
    expect(offset == len(blob), f"PLY body has {len(blob) - offset} bytes after its faces")
    expect(all(len(f["vertex_indices"]) == 3 for f in faces), "PLY face that is not a triangle")
    points = [(v["x"], v["y"], v["z"]) for v in vertices]
    normals = [(v["nx"], v["ny"], v["nz"]) for v in vertices]
    return points, normals, [f["vertex_indices"] for f in faces], [f["part"] for f in faces]


def obj_index(word, count):
    i = int(word.split("/")[0])
    return i - 1 if i > 0 else count + i


def read_obj(path):
    """Returns (points, normal count, faces) of an OBJ file of triangles."""
    points, normal_count, faces = [], 0, []
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "v":
                points.append(tuple(float(w) for w in words[1:4]))
            elif words[0] == "vn":
                normal_count += 1
            elif words[0] == "f":
                expect(len(words) == 4, f"OBJ face that is not a triangle: {line.strip()}")
                faces.append(tuple(obj_index(w, len(points)) for w in words[1:]))
    return points, normal_count, faces


def read_stl(path):
    """Returns (points, faces) of a binary STL, corners welded by exact position."""
    with open(path, "rb") as f:
        blob = f.read()
    expect(len(blob) >= 84, "STL shorter than its header")
    (count,) = struct.unpack_from("<I", blob, 80)
    expect(len(blob) == 84 + 50 * count,
           f"STL of {len(blob)} bytes declares {count} triangles ({84 + 50 * count} bytes)")
    index, points, faces = {}, [], []
    for t in struct.iter_unpack("<12fH", blob[84:]):
        face = []
        for corner in (t[3:6], t[6:9], t[9:12]):
            if corner not in index:
                index[corner] = len(points)
                points.append(corner)
            face.append(index[corner])
        faces.append(tuple(face))
    return points, faces


def check_closed(faces, vertex_count, what):
    """Every edge in exactly two triangles, traversed once each way (closed,
    manifold, consistently oriented); indices in range; no repeated corner."""
    expect(faces, f"{what}: no triangles")
    directed = Counter()
    for a, b, c in faces:
        expect(a != b and b != c and a != c, f"{what}: triangle with a repeated vertex {a, b, c}")
        directed.update(((a, b), (b, c), (c, a)))
    expect(max(max(f) for f in faces) < vertex_count and min(min(f) for f in faces) >= 0,
           f"{what}: vertex index out of range")
    undirected = Counter()
    for (a, b), n in directed.items():
        undirected[(min(a, b), max(a, b))] += n
    open_edges = sum(1 for n in undirected.values() if n == 1)
    other = sum(1 for n in undirected.values() if n > 2)
    expect(open_edges == 0 and other == 0,
           f"{what}: {open_edges} boundary and {other} non-manifold edges")
    twice = sum(1 for n in directed.values() if n > 1)
    expect(twice == 0, f"{what}: {twice} edges traversed twice the same way (inconsistent)")


def signed_volume(points, faces):
    total = 0.0
    for a, b, c in faces:
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = points[a], points[b], points[c]
        total += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)
    return total / 6.0


def check_ply_mesh(path, summary=None):
    """Parses a written PLY, checks it is a closed oriented mesh with unit
    normals, matches the --json summary if given; returns (points, normals, faces, parts)."""
    expect(os.path.isfile(path), f"{path} was not written")
    points, normals, faces, parts = read_ply(path)
    check_closed(faces, len(points), path)
    bad = sum(1 for n in normals if not close_to(math.sqrt(sum(c * c for c in n)), 1.0, 1e-3))
    expect(bad == 0, f"{path}: {bad} normals are not unit length")
    expect(signed_volume(points, faces) > 0, f"{path}: triangles face inward (negative volume)")
    part_ids = set(parts)
    expect(part_ids == set(range(len(part_ids))), f"{path}: part ids are not 0..P-1")
    if summary is not None:
        expect(summary["vertices"] == len(points) and summary["triangles"] == len(faces),
               f"summary says {summary['vertices']} vertices, {summary['triangles']} triangles;"
               f" {path} has {len(points)}, {len(faces)}")
        expect(summary["parts"] == len(part_ids),
               f"summary says {summary['parts']} parts; {path} has {len(part_ids)}")
        expect(summary["boundary_edges"] == 0 and summary["nonmanifold_edges"] == 0,
               f"summary reports open or non-manifold edges: {summary}")
    return points, normals, faces, parts


def leftovers(folder, allowed):
    """Files in folder other than allowed: outputs or temporary files left behind."""
    return sorted(set(os.listdir(folder)) - set(allowed))


# ---------------------------------------------------------------- help, usage

COMMAND_OPTIONS = {
    "info": ["--json"],
    "contour": ["--grid", "--iso", "--method", "--orientation", "--threads", "--output",
                "--progress", "--quiet", "--json"],
    "convert": ["--output", "--dims", "--type", "--endian", "--spacing", "--origin",
                "--header-bytes", "--json"],
    "pipeline": ["--output", "--size", "--iso", "--method", "--threads", "--keep", "--level", "--json"],
}


def case_top_help(tmp):
    proc = run("--help")
    for command in COMMAND_OPTIONS:
        expect(command in proc.stdout, f"isoform --help does not list {command}")


def case_command_help(tmp):
    for command, options in COMMAND_OPTIONS.items():
        proc = run(command, "--help")
        missing = [o for o in options if o not in proc.stdout]
        expect(not missing, f"isoform {command} --help does not name {missing}")


def case_version(tmp):
    expect(run("--version").stdout.startswith("isoform "), "--version does not say isoform")


def case_usage_errors(tmp):
    out = os.path.join(tmp, "out.ply")
    for args in ([], ["frobnicate"], ["contour"], ["contour", "in.vdb"],
                 ["contour", "in.vdb", "-o", out, "--method", "bogus"],
                 ["contour", "in.vdb", "-o", out, "--threads", "-1"],
                 ["contour", "in.vdb", "-o", out, "--progress", "--quiet"],
                 ["convert", "in.raw", "-o", "x.vdb", "--dims", "1,2"],
                 ["convert", "in.raw", "-o", "x.vdb", "--dims", "4,4,4", "--type", "u7"],
                 ["info", "a.vdb", "--no-such-option"]):
        proc = run(*args, code=2)
        expect(proc.stderr.strip(), f"isoform {' '.join(args)}: no usage message")
    expect(leftovers(tmp, []) == [], "a usage error wrote a file")


# ---------------------------------------------------------------- info

def case_info_sphere_json(tmp):
    report, _ = run_json("info", data("sphere.vdb"))
    grids = report["grids"]
    expect(len(grids) == 1, f"sphere.vdb has {len(grids)} grids, expected 1")
    g = grids[0]
    expect(g["name"] == "ls_sphere", f"grid name {g['name']}")
    expect(g["class"] == "level set", f"class {g['class']}")
    expect(g["scalar"] is True, "ls_sphere is not scalar")
    expect(g["active_voxels"] == 270638, f"active voxels {g['active_voxels']}")
    expect(all(close_to(v, 0.05, 1e-6) for v in g["voxel_size"]), f"voxel size {g['voxel_size']}")
    expect(g["bbox_min"] == [-62] * 3 and g["bbox_max"] == [62] * 3,
           f"bbox {g['bbox_min']}..{g['bbox_max']}")
    expect(close_to(g["background"], 0.15, 1e-3), f"background {g['background']}")
    expect(len(g["transform"]) == 4 and all(len(r) == 4 for r in g["transform"]),
           "transform is not 4x4")
    expect(close_to(g["transform"][0][0], 0.05, 1e-6) and g["transform"][3] == [0, 0, 0, 1],
           f"transform {g['transform']}")


def case_info_sphere_text(tmp):
    out = run("info", data("sphere.vdb")).stdout
    for word in ("ls_sphere", "level set", "270638", "0.05"):
        expect(word in out, f"info text lacks {word!r}:\n{out}")


def case_info_smoke_json(tmp):
    g = run_json("info", data("smoke.vdb"))[0]["grids"][0]
    expect(g["name"] == "density" and g["class"] == "fog volume", f"{g['name']}, {g['class']}")
    expect(g["active_voxels"] == 1049275, f"active voxels {g['active_voxels']}")
    expect(g["bbox_min"] == [1, 2, 1] and g["bbox_max"] == [111, 223, 112],
           f"bbox {g['bbox_min']}..{g['bbox_max']}")
    expect(close_to(g["value_max"], 5.71, 0.01) and g["value_min"] < 1e-3,
           f"value range {g['value_min']}..{g['value_max']}")


# ---------------------------------------------------------------- contours

def case_contour_sphere_ply(tmp):
    out = os.path.join(tmp, "sphere.ply")
    summary, proc = run_json("contour", data("sphere.vdb"), "-o", out)
    expect(proc.stderr == "", f"a level set with the default isovalue printed: {proc.stderr}")
    expect(summary["isovalue"] == 0 and summary["grid"] == "ls_sphere", f"{summary}")
    points, normals, _, _ = check_ply_mesh(out, summary)
    expect(summary["parts"] == 1, f"the sphere has {summary['parts']} parts")
    expect(summary["euler_characteristic"] == 2, f"Euler characteristic {summary}")
    radii = [math.sqrt(sum(c * c for c in p)) for p in points]
    mean = sum(radii) / len(radii)
    expect(max(radii) - mean < 0.025 and mean - min(radii) < 0.025,
           f"vertex radii {min(radii)}..{max(radii)} stray over half a voxel from {mean}")
    inward = sum(1 for p, n in zip(points, normals) if sum(a * b for a, b in zip(p, n)) <= 0)
    expect(inward == 0, f"{inward} normals of the level-set sphere point inward")
    expect(leftovers(tmp, ["sphere.ply"]) == [], f"left behind: {leftovers(tmp, ['sphere.ply'])}")


def case_contour_sphere_obj_stl(tmp):
    ply, obj, stl = (os.path.join(tmp, "s." + e) for e in ("ply", "obj", "stl"))
    for out in (ply, obj, stl):
        run("contour", data("sphere.vdb"), "-o", out)
    ply_points, _, ply_faces, _ = read_ply(ply)
    points, normal_count, faces = read_obj(obj)
    check_closed(faces, len(points), obj)
    expect(len(points) == len(ply_points) and len(faces) == len(ply_faces),
           f"OBJ has {len(points)} v, {len(faces)} f; PLY {len(ply_points)}, {len(ply_faces)}")
    expect(normal_count == len(points), f"OBJ has {normal_count} vn for {len(points)} v")
    expect(signed_volume(points, faces) > 0, f"{obj}: triangles face inward")
    points, faces = read_stl(stl)
    check_closed(faces, len(points), stl)
    expect(len(faces) == len(ply_faces), f"STL has {len(faces)} triangles; PLY {len(ply_faces)}")


def case_contour_sphere_tetra(tmp):
    out = os.path.join(tmp, "tetra.ply")
    summary, _ = run_json("contour", data("sphere.vdb"), "--method", "tetra", "--threads", "1",
                          "-o", out)
    expect(summary["method"] == "tetra", f"method {summary['method']}")
    check_ply_mesh(out, summary)


def case_contour_sphere_flipped(tmp):
    out = os.path.join(tmp, "inside.ply")
    run("contour", data("sphere.vdb"), "--orientation", "decreasing", "-o", out)
    points, _, faces, _ = read_ply(out)
    expect(signed_volume(points, faces) < 0, "--orientation decreasing did not flip the triangles")


def case_contour_smoke_ply(tmp):
    out = os.path.join(tmp, "smoke.ply")
    summary, proc = run_json("contour", data("smoke.vdb"), "--iso", "0.5", "-o", out)
    expect(proc.stderr == "", f"a given --iso printed: {proc.stderr}")
    expect(summary["isovalue"] == 0.5 and not summary["isovalue_was_auto"], f"{summary}")
    check_ply_mesh(out, summary)


def case_contour_smoke_auto_stl(tmp):
    out = os.path.join(tmp, "smoke.stl")
    summary, proc = run_json("contour", data("smoke.vdb"), "-o", out)
    g = run_json("info", data("smoke.vdb"))[0]["grids"][0]
    middle = (g["value_min"] + g["value_max"]) / 2
    expect(summary["isovalue_was_auto"] and close_to(summary["isovalue"], middle, 1e-6 * middle),
           f"automatic isovalue {summary['isovalue']}, expected the midpoint {middle}")
    lines = proc.stderr.splitlines()
    expect(len(lines) == 1 and "isovalue" in lines[0] and "--iso" in lines[0],
           f"expected one note naming the chosen isovalue and --iso, got: {proc.stderr}")
    points, faces = read_stl(out)
    check_closed(faces, len(points), out)
    expect(len(faces) == summary["triangles"], f"STL {len(faces)} triangles; summary {summary}")


def case_contour_smoke_quiet_obj(tmp):
    out = os.path.join(tmp, "smoke.obj")
    proc = run("contour", data("smoke.vdb"), "--quiet", "-o", out)
    expect(proc.stderr == "", f"--quiet printed: {proc.stderr}")
    expect("triangles" in proc.stdout and out in proc.stdout, f"summary: {proc.stdout}")
    points, _, faces = read_obj(out)
    check_closed(faces, len(points), out)


# ---------------------------------------------------------------- convert

HEAD_RAW = "headsq_64x64x93_u16le.raw"
HEAD_LAYOUT = ["--dims", "64,64,93", "--type", "u16", "--spacing", "3.2,3.2,1.5"]


def case_convert_head(tmp):
    vdb = os.path.join(tmp, "head.vdb")
    report, _ = run_json("convert", data(HEAD_RAW), "-o", vdb, *HEAD_LAYOUT)
    expect(report["output"] == vdb and len(report["grids"]) == 1, f"{report}")
    expect(leftovers(tmp, ["head.vdb"]) == [], f"left behind: {leftovers(tmp, ['head.vdb'])}")
    g = run_json("info", vdb)[0]["grids"][0]
    expect(all(lo >= 0 for lo in g["bbox_min"]) and
           all(hi <= top for hi, top in zip(g["bbox_max"], (63, 63, 92))),
           f"bbox {g['bbox_min']}..{g['bbox_max']} outside 0..63, 0..63, 0..92")
    expect(all(close_to(a, b, 1e-9) for a, b in zip(g["voxel_size"], (3.2, 3.2, 1.5))),
           f"voxel size {g['voxel_size']}")
    expect(g["value_max"] <= 3926, f"value max {g['value_max']}")
    ply = os.path.join(tmp, "head.ply")
    summary, _ = run_json("contour", vdb, "--iso", "500", "-o", ply)
    check_ply_mesh(ply, summary)


def write_ball_nrrd(path, gzipped):
    """A 20^3 float NRRD of density max(0, 1 - r/8) around the array's middle,
    with spacing 0.5: its 0.5 contour is a sphere of radius 2 world units."""
    n, middle, radius = 20, 9.5, 8.0
    samples = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                r = math.sqrt((i - middle) ** 2 + (j - middle) ** 2 + (k - middle) ** 2)
                samples.append(max(0.0, 1.0 - r / radius))
    body = struct.pack(f"<{len(samples)}f", *samples)
    header = (f"NRRD0004\ntype: float\ndimension: 3\nsizes: {n} {n} {n}\n"
              f"spacings: 0.5 0.5 0.5\nendian: little\n"
              f"encoding: {'gzip' if gzipped else 'raw'}\n\n")
    with open(path, "wb") as f:
        f.write(header.encode("ascii") + (gzip.compress(body) if gzipped else body))


def case_convert_nrrd(tmp):
    for name, gzipped in (("ball.nrrd", False), ("ballz.nrrd", True)):
        nrrd, vdb = os.path.join(tmp, name), os.path.join(tmp, name + ".vdb")
        write_ball_nrrd(nrrd, gzipped)
        run("convert", nrrd, "-o", vdb)
        g = run_json("info", vdb)[0]["grids"][0]
        expect(all(close_to(v, 0.5, 1e-9) for v in g["voxel_size"]), f"voxel size {g}")
        ply = os.path.join(tmp, name + ".ply")
        summary, _ = run_json("contour", vdb, "--iso", "0.5", "-o", ply)
        points, _, _, _ = check_ply_mesh(ply, summary)
        centre = [sum(p[axis] for p in points) / len(points) for axis in range(3)]
        radii = [math.dist(p, centre) for p in points]
        expect(all(close_to(r, 2.0, 0.25) for r in radii),
               f"{name}: contour radii {min(radii)}..{max(radii)}, expected about 2")


def case_convert_raw_needs_dims(tmp):
    vdb = os.path.join(tmp, "head.vdb")
    proc = run("convert", data(HEAD_RAW), "-o", vdb, code=1)
    check_one_error_line(proc, [HEAD_RAW, "--dims"])
    expect(leftovers(tmp, []) == [], f"left behind: {leftovers(tmp, [])}")


def case_convert_raw_wrong_size(tmp):
    vdb = os.path.join(tmp, "head.vdb")
    proc = run("convert", data(HEAD_RAW), "-o", vdb, "--dims", "64,64,92", code=1)
    check_one_error_line(proc, [HEAD_RAW])
    expect(leftovers(tmp, []) == [], f"left behind: {leftovers(tmp, [])}")


# ---------------------------------------------------------------- bad input

def check_one_error_line(proc, mentions):
    lines = proc.stderr.splitlines()
    expect(len(lines) == 1 and lines[0].startswith("isoform: error: "),
           f"expected one 'isoform: error:' line on stderr, got: {proc.stderr!r}")
    missing = [m for m in mentions if m not in lines[0]]
    expect(not missing, f"error line does not name {missing}: {lines[0]}")
    expect(proc.stdout == "", f"a failure printed a summary: {proc.stdout}")


def expect_failure(tmp, args, mentions, inputs):
    """isoform args exits 1 with one line naming mentions; tmp keeps only inputs."""
    proc = run(*args, code=1)
    check_one_error_line(proc, mentions)
    left = leftovers(tmp, inputs)
    expect(left == [], f"isoform {' '.join(args)} left behind {left}")


def case_missing_input(tmp):
    missing = os.path.join(tmp, "missing.vdb")
    expect_failure(tmp, ["contour", missing, "-o", os.path.join(tmp, "out.ply")],
                   ["missing.vdb"], [])
    expect_failure(tmp, ["info", missing], ["missing.vdb"], [])
    expect_failure(tmp, ["convert", missing, "-o", os.path.join(tmp, "out.vdb")],
                   ["missing.vdb"], [])


def case_text_file_named_vdb(tmp):
    fake = os.path.join(tmp, "x.vdb")
    with open(fake, "w") as f:
        f.write("this is not a VDB file\n" * 20)
    expect_failure(tmp, ["contour", fake, "-o", os.path.join(tmp, "out.ply")], ["x.vdb"], ["x.vdb"])
    expect_failure(tmp, ["info", fake], ["x.vdb"], ["x.vdb"])
    expect_failure(tmp, ["convert", fake, "-o", os.path.join(tmp, "out.vdb")], ["x.vdb"],
                   ["x.vdb"])


def case_truncated_vdb(tmp):
    with open(data("sphere.vdb"), "rb") as f:
        blob = f.read()
    for name, size in (("head.vdb", 200), ("half.vdb", len(blob) // 2)):
        cut = os.path.join(tmp, name)
        with open(cut, "wb") as f:
            f.write(blob[:size])
        expect_failure(tmp, ["contour", cut, "-o", os.path.join(tmp, "out.ply")], [name],
                       ["head.vdb", "half.vdb"])


def copy_sphere(tmp):
    copy = os.path.join(tmp, "in.vdb")
    shutil.copyfile(data("sphere.vdb"), copy)
    return copy


def case_unknown_grid(tmp):
    sphere = copy_sphere(tmp)
    expect_failure(tmp, ["contour", sphere, "--grid", "nosuch", "-o", os.path.join(tmp, "o.ply")],
                   ["in.vdb", "nosuch", "ls_sphere"], ["in.vdb"])


def case_isovalue_outside_range(tmp):
    sphere = copy_sphere(tmp)
    expect_failure(tmp, ["contour", sphere, "--iso", "99", "-o", os.path.join(tmp, "o.ply")],
                   ["in.vdb", "99", "outside", "ls_sphere"], ["in.vdb"])


def case_unwritable_output(tmp):
    sphere = copy_sphere(tmp)
    expect_failure(tmp, ["contour", sphere, "-o", os.path.join(tmp, "nowhere", "o.ply")],
                   ["nowhere"], ["in.vdb"])
    expect_failure(tmp, ["convert", sphere, "-o", os.path.join(tmp, "nowhere", "o.vdb")],
                   ["nowhere"], ["in.vdb"])


def case_output_is_input(tmp):
    sphere = copy_sphere(tmp)
    before = sha256(sphere)
    expect_failure(tmp, ["contour", sphere, "-o", sphere], ["in.vdb"], ["in.vdb"])
    expect_failure(tmp, ["convert", sphere, "-o", sphere], ["in.vdb"], ["in.vdb"])
    link = os.path.join(tmp, "link.ply")
    os.symlink("in.vdb", link)
    expect_failure(tmp, ["contour", sphere, "-o", link], ["in.vdb", "link.ply"],
                   ["in.vdb", "link.ply"])
    expect(os.path.islink(link), "the symlink to the input was replaced")
    expect(sha256(sphere) == before, "the input file changed")


def case_unknown_output_extension(tmp):
    sphere = copy_sphere(tmp)
    expect_failure(tmp, ["contour", sphere, "-o", os.path.join(tmp, "o.xyz")], ["o.xyz"],
                   ["in.vdb"])
    expect_failure(tmp, ["convert", sphere, "-o", os.path.join(tmp, "o.ply")], ["o.ply"],
                   ["in.vdb"])


GROUPS = {
    "help_usage": [case_top_help, case_command_help, case_version, case_usage_errors],
    "info": [case_info_sphere_json, case_info_sphere_text, case_info_smoke_json],
    "contour_sphere": [case_contour_sphere_ply, case_contour_sphere_obj_stl,
                       case_contour_sphere_tetra, case_contour_sphere_flipped],
    "contour_smoke": [case_contour_smoke_ply, case_contour_smoke_auto_stl,
                      case_contour_smoke_quiet_obj],
    "convert_head": [case_convert_head, case_convert_nrrd, case_convert_raw_needs_dims, case_convert_raw_wrong_size],
    "bad_input": [case_missing_input, case_text_file_named_vdb, case_truncated_vdb,
                  case_unknown_grid, case_isovalue_outside_range, case_unwritable_output,
                  case_output_is_input, case_unknown_output_extension],
}


def run_groups(groups, argv):
    """Runs the cases of the group named in argv (ISOFORM_BINARY SHARED_DATA_DIR GROUP),
    each in a fresh temporary folder, and exits non-zero if any failed."""
    global BINARY, DATA
    if len(argv) != 4 or argv[3] not in groups:
        sys.exit(f"usage: {argv[0]} ISOFORM_BINARY SHARED_DATA_DIR {{{','.join(groups)}}}")
    BINARY, DATA, group = os.path.abspath(argv[1]), argv[2], argv[3]
    failed = 0
    for case in groups[group]:
        with tempfile.TemporaryDirectory(prefix="isoform-cli-") as tmp:
            try:
                case(tmp)
                print(f"PASS {case.__name__}")
            except CaseFailure as failure:
                failed += 1
                print(f"FAIL {case.__name__}: {failure}")
            except Exception:
                failed += 1
                print(f"FAIL {case.__name__}: unexpected error\n{traceback.format_exc()}")
    print(f"{group}: {len(groups[group]) - failed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    run_groups(GROUPS, sys.argv)
