"""The `isoform reduce` command and `contour --reduce`, run as a program:
closed contours stay closed with the same genus and parts, --keep as a
percentage or a fraction, the boundary lock, --json, and bad input. Shares
test_cli.py's helpers.

Usage: test_cli_reduce.py ISOFORM_BINARY SHARED_DATA_DIR GROUP"""
import os
import struct
import sys
from collections import Counter

import test_cli as base
from test_cli import expect, run, run_json, data, leftovers, expect_failure, check_one_error_line, sha256


def euler(points, faces):
    edges = {(min(a, b), max(a, b)) for f in faces for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0]))}
    return len(points) - len(edges) + len(faces)


def parts(faces):
    """Connected parts over shared edges (as the library counts them)."""
    parent = list(range(len(faces)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    first = {}
    for i, f in enumerate(faces):
        for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            key = (min(a, b), max(a, b))
            if key in first:
                parent[find(i)] = find(first[key])
            else:
                first[key] = i
    return len({find(i) for i in range(len(faces))})


def boundary_points(points, faces):
    count = Counter((min(a, b), max(a, b)) for f in faces for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])))
    return {points[v] for e, n in count.items() if n == 1 for v in e}


def write_grid_obj(path, n):
    """An n x n grid of the paraboloid z = .4(x^2 + y^2) over [-1, 1]^2 (a mesh with a boundary)."""
    with open(path, "w") as f:
        for j in range(n):
            for i in range(n):
                x, y = -1 + 2 * i / (n - 1), -1 + 2 * j / (n - 1)
                f.write(f"v {x:.9g} {y:.9g} {0.4 * (x * x + y * y):.9g}\n")
        for j in range(n - 1):
            for i in range(n - 1):
                a = j * n + i + 1
                f.write(f"f {a} {a + 1} {a + n + 1}\nf {a} {a + n + 1} {a + n}\n")


def write_obj(path, points, faces, mode="w"):
    with open(path, mode) as f:
        for p in points:
            f.write("v %.9g %.9g %.9g\n" % p)
        for a, b, c in faces:
            f.write(f"f {a + 1} {b + 1} {c + 1}\n")


def expect_refused(tmp, args, path, message, inputs):
    """Exit 1, one line that starts with the file and message, no output, input untouched."""
    digest = sha256(path)
    proc = run(*args, code=1)
    check_one_error_line(proc, [path])
    expect(proc.stderr.startswith(f"isoform: error: {path}: {message}"), f"error line: {proc.stderr!r}")
    left = leftovers(tmp, inputs)
    expect(left == [], f"isoform {' '.join(args)} left behind {left}")
    expect(sha256(path) == digest, f"isoform {' '.join(args)} changed its input")


def case_help(tmp):
    proc = run("reduce", "--help")
    for option in ("--keep", "--tolerance", "--lock-boundary", "--point", "--no-overlap", "--graph",
                   "--rms-tolerance", "--json", "--progress", "--quiet"):
        expect(option in proc.stdout, f"reduce --help does not mention {option}")
    expect("--reduce" in run("contour", "--help").stdout, "contour --help does not mention --reduce")


def case_cube_reduced_90(tmp):
    """cube.vdb's contour reduced by 90%: closed, manifold, same genus and parts."""
    mesh = os.path.join(tmp, "cube.obj")
    run("contour", data("cube.vdb"), "-o", mesh)
    points, _, faces = base.read_obj(mesh)
    out = os.path.join(tmp, "small.obj")
    summary, _ = run_json("reduce", mesh, "--keep", "10%", "-o", out)
    small_points, _, small = base.read_obj(out)
    base.check_closed(small, len(small_points), out)
    expect(summary["triangles_before"] == len(faces) and summary["triangles_after"] == len(small),
           f"summary {summary['triangles_before']} -> {summary['triangles_after']}, files {len(faces)} -> {len(small)}")
    expect(len(small) <= 0.1 * len(faces), f"{len(small)} of {len(faces)} triangles kept")
    expect(euler(small_points, small) == euler(points, faces), "Euler characteristic changed")
    expect(parts(small) == parts(faces) == summary["parts"], f"parts {parts(faces)} -> {parts(small)}")
    expect(summary["max_vertex_distance"] > 0, f"no error measured: {summary}")
    expect(sorted(leftovers(tmp, [])) == ["cube.obj", "small.obj"], f"left {leftovers(tmp, [])}")


def case_contour_reduce(tmp):
    """contour --reduce 90% chains the reduction; the same as reduce --keep 0.1."""
    direct = os.path.join(tmp, "sphere.obj")
    summary, _ = run_json("contour", data("sphere.vdb"), "--reduce", "90%", "-o", direct)
    points, _, faces = base.read_obj(direct)
    base.check_closed(faces, len(points), direct)
    r = summary["reduce"]
    expect(r["triangles_after"] == len(faces) == summary["triangles"], f"{r} vs {len(faces)}")
    expect(len(faces) <= 0.1 * r["triangles_before"], f"{len(faces)} of {r['triangles_before']}")
    expect(euler(points, faces) == 2, "the sphere is no longer a sphere")
    full = os.path.join(tmp, "full.obj")
    run("contour", data("sphere.vdb"), "-o", full)
    again = os.path.join(tmp, "again.obj")
    run("reduce", full, "--keep", "0.1", "-o", again)
    expect(base.read_obj(again)[2] == faces, "contour --reduce 90% differs from reduce --keep 0.1")
    # 0% checks and copies; an empty or whole share is refused before any work, with no output.
    copy = os.path.join(tmp, "copy.obj")
    summary, _ = run_json("contour", data("sphere.vdb"), "--reduce", "0%", "-o", copy)
    expect(summary["reduce"]["triangles_after"] == summary["reduce"]["triangles_before"], f"{summary}")
    expect(base.read_obj(copy)[2] == base.read_obj(full)[2], "contour --reduce 0% changed the mesh")
    for share, message in (("", "is not a fraction"), ("100%", "would remove every triangle")):
        bad = os.path.join(tmp, "bad.obj")
        proc = run("contour", data("sphere.vdb"), "--reduce", share, "-o", bad, code=1)
        expect(message in proc.stderr and not os.path.exists(bad), f"--reduce {share!r}: {proc.stderr!r}")


def case_keep_all_is_a_copy(tmp):
    mesh = os.path.join(tmp, "cube.obj")
    run("contour", data("cube.vdb"), "-o", mesh)
    out = os.path.join(tmp, "copy.obj")
    summary, _ = run_json("reduce", mesh, "--keep", "100%", "-o", out)
    a, b = base.read_obj(mesh), base.read_obj(out)
    expect(a[0] == b[0] and a[2] == b[2], "--keep 100% changed the mesh")
    expect(summary["removals"] == 0, f"{summary}")


def case_boundary(tmp):
    """A mesh with a boundary reduces; --lock-boundary keeps every boundary vertex."""
    mesh = os.path.join(tmp, "grid.obj")
    write_grid_obj(mesh, 21)
    points, _, faces = base.read_obj(mesh)
    rim = boundary_points(points, faces)
    free_out, locked_out = os.path.join(tmp, "free.obj"), os.path.join(tmp, "locked.obj")
    run("reduce", mesh, "--keep", "20%", "-o", free_out)
    run("reduce", mesh, "--keep", "20%", "--lock-boundary", "-o", locked_out)
    fp, _, ff = base.read_obj(free_out)
    lp, _, lf = base.read_obj(locked_out)
    expect(euler(fp, ff) == euler(lp, lf) == 1, "a disk is no longer a disk")
    expect(boundary_points(lp, lf) == rim, "--lock-boundary lost boundary vertices")
    expect(len(boundary_points(fp, ff)) < len(rim), "without the lock no boundary vertex went")
    expect(len(ff) <= 0.2 * len(faces), f"{len(ff)} of {len(faces)} kept")


def case_single_triangle(tmp):
    mesh = os.path.join(tmp, "one.obj")
    with open(mesh, "w") as f:
        f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    out = os.path.join(tmp, "out.obj")
    summary, _ = run_json("reduce", mesh, "-o", out)
    expect(len(base.read_obj(out)[2]) == 1 and summary["removals"] == 0, f"{summary}")


def case_bad_input(tmp):
    fin = os.path.join(tmp, "fin.obj")
    with open(fin, "w") as f:
        f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n")
    out = os.path.join(tmp, "out.obj")
    expect_failure(tmp, ["reduce", fin, "-o", out], ["fin.obj", "not manifold", "edge (0, 1)"], ["fin.obj"])
    nan = os.path.join(tmp, "nan.obj")
    with open(nan, "w") as f:
        f.write("v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n")
    expect_refused(tmp, ["reduce", nan, "-o", out], nan, "line 2: v has a value that is not finite",
                   ["fin.obj", "nan.obj"])
    for keep in ("0%", "150%", "ten"):
        expect_failure(tmp, ["reduce", fin, "--keep", keep, "-o", out], ["--keep", keep], ["fin.obj", "nan.obj"])
    expect_failure(tmp, ["reduce", fin, "-o", fin], ["fin.obj"], ["fin.obj", "nan.obj"])
    expect_failure(tmp, ["contour", data("cube.vdb"), "--reduce", "100%", "-o", out], ["--reduce"],
                   ["fin.obj", "nan.obj"])


def case_overlap(tmp):
    """Two triangles through each other: named, with where they cross."""
    cross = os.path.join(tmp, "cross.obj")
    write_obj(cross, [(0, 0, 0), (2, 0, 0), (0, 2, 0), (0.5, 0.5, -1), (0.5, 0.5, 1), (0.6, 0.6, 0.5)],
              [(0, 1, 2), (3, 4, 5)])
    out = os.path.join(tmp, "out.ply")
    expect_refused(tmp, ["reduce", cross, "-o", out], cross,
                   "the mesh overlaps itself: triangles 0 and 1 intersect (near 0.5, 0.5, 0)", ["cross.obj"])
    expect_refused(tmp, ["reduce", cross, "--keep", "100%", "-o", out], cross, "the mesh overlaps itself",
                   ["cross.obj"])


def case_nan_ply(tmp):
    """A binary PLY with a NaN coordinate: the line names the file and the vertex."""
    path = os.path.join(tmp, "nan.ply")
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
              "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n")
    body = b"".join(struct.pack("<3f", *p) for p in ((0, 0, 0), (1, 0, float("nan")), (0, 1, 0)))
    with open(path, "wb") as f:
        f.write(header.encode("ascii") + body + struct.pack("<B3i", 3, 0, 1, 2))
    expect_refused(tmp, ["reduce", path, "-o", os.path.join(tmp, "out.ply")], path,
                   "vertex 1 has z = nan, which is not a finite float", ["nan.ply"])


FIN = [(5, 0, 0), (6, 0, 0), (5, 1, 0), (5, -1, 0), (5, 0, 1)]


def case_manifold_parts(tmp):
    """--manifold-parts: a fin beside a grid is copied and named, the grid reduced."""
    mesh = os.path.join(tmp, "grid_fin.obj")
    write_grid_obj(mesh, 21)  # vertices 0-440, triangles 0-799
    v = 441
    write_obj(mesh, FIN, [(v, v + 1, v + 2), (v + 1, v, v + 3), (v, v + 1, v + 4)], "a")
    out = os.path.join(tmp, "out.obj")
    expect_refused(tmp, ["reduce", mesh, "-o", out], mesh,
                   "the mesh is not manifold: edge (441, 442) is shared by 3 triangles", ["grid_fin.obj"])
    summary, _ = run_json("reduce", mesh, "--keep", "20%", "--manifold-parts", "-o", out)
    reason = "part of 3 triangles from triangle 800: the mesh is not manifold: edge (441, 442) is shared by 3 triangles"
    expect(summary["parts_left_alone"] == 1 and summary["triangles_left_alone"] == 3, f"{summary}")
    expect(summary["left_alone"] == [reason], f"{summary['left_alone']}")
    expect(summary["triangles_before"] == 803, f"{summary}")
    points, _, faces = base.read_obj(out)
    expect(len(faces) - 3 <= 160 and len(faces) - 3 > 100, f"{len(faces)} triangles: --keep counts the grid's 800")
    fin = [tuple(points[v] for v in f) for f in faces[-3:]]
    expect(fin == [(FIN[0], FIN[1], FIN[2]), (FIN[1], FIN[0], FIN[3]), (FIN[0], FIN[1], FIN[4])],
           f"the fin was not copied unchanged: {fin}")
    text = run("reduce", mesh, "--manifold-parts", "-o", out).stdout
    expect("left alone" in text and reason in text, text)
    expect(leftovers(tmp, ["grid_fin.obj", "out.obj"]) == [], "files left behind")


def case_keep_all_is_bit_identical(tmp):
    """--keep 100% writes the same file as a plain conversion would: binary PLY byte for byte."""
    mesh = os.path.join(tmp, "sphere.ply")
    run("contour", data("sphere.vdb"), "-o", mesh)
    out = os.path.join(tmp, "copy.ply")
    run("reduce", mesh, "--keep", "100%", "-o", out)
    with open(mesh, "rb") as a, open(out, "rb") as b:
        expect(a.read() == b.read(), "--keep 100% did not write the input's bytes")


def case_curvature_in_the_file(tmp):
    """A PLY that carries curvature (written by `isoform curvature`) comes back byte for byte with
    --keep 100%, and the reduction takes its curvature instead of computing it again."""
    mesh = os.path.join(tmp, "sphere.ply")
    run("contour", data("sphere.vdb"), "-q", "-o", mesh)
    curved = os.path.join(tmp, "curved.ply")
    run("curvature", mesh, "--method", "seed", "-q", "-o", curved)
    copy = os.path.join(tmp, "copy.ply")
    run("reduce", curved, "--keep", "100%", "-o", copy)
    with open(curved, "rb") as a, open(copy, "rb") as b:
        expect(a.read() == b.read(), "--keep 100% of a file with curvature did not write its bytes")
    summary, _ = run_json("reduce", curved, "--keep", "20%", "-o", os.path.join(tmp, "small.ply"))
    expect(summary["curvature_computed"] is False, f"the file's curvature was not used: {summary}")
    summary, _ = run_json("reduce", mesh, "--keep", "20%", "-o", os.path.join(tmp, "small2.ply"))
    expect(summary["curvature_computed"] is True, f"{summary}")


def write_double_torus_ply(path, offset, rings=24, sides=12):
    """A torus (radii 2 and 0.7) at x = offset, its points as doubles in a binary PLY."""
    import math
    points, faces = [], []
    for i in range(rings):
        for j in range(sides):
            u, v = 2 * math.pi * i / rings, 2 * math.pi * j / sides
            r = 2 + 0.7 * math.cos(v)
            points.append((offset + r * math.cos(u), r * math.sin(u), 0.7 * math.sin(v)))
    for i in range(rings):
        for j in range(sides):
            a, b = i * sides + j, ((i + 1) % rings) * sides + j
            c, d = ((i + 1) % rings) * sides + (j + 1) % sides, i * sides + (j + 1) % sides
            faces += [(a, b, c), (a, c, d)]
    header = ("ply\nformat binary_little_endian 1.0\n"
              f"element vertex {len(points)}\nproperty double x\nproperty double y\nproperty double z\n"
              f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
    with open(path, "wb") as f:
        f.write(header.encode())
        for p in points:
            f.write(struct.pack("<3d", *p))
        for t in faces:
            f.write(struct.pack("<B3i", 3, *t))
    return points, faces


def case_double_points_far_from_the_origin(tmp):
    """Ten million units from the origin floats are 1 apart: a double-precision PLY is reduced in
    double (no false overlap), closed with the same genus, and written in double."""
    path = os.path.join(tmp, "far.ply")
    points, faces = write_double_torus_ply(path, 1e7)
    out = os.path.join(tmp, "small.obj")
    summary, _ = run_json("reduce", path, "--keep", "30%", "-o", out)
    small_points, _, small = base.read_obj(out)
    # Floats there are whole numbers: fractions show the points went out in double.
    expect(sum(p[0] != round(p[0]) for p in small_points) > len(small_points) // 2,
           "the far torus was written in float")
    base.check_closed(small, len(small_points), out)
    expect(euler(small_points, small) == 0, "the torus lost its genus")
    expect(all(abs(p[0] - 1e7) < 3 and abs(p[1]) < 3 and abs(p[2]) < 1 for p in small_points),
           "points moved off the torus")


def case_concave_polygon(tmp):
    """An OBJ face that is a concave pentagon is split without overlap and passes the checks."""
    path = os.path.join(tmp, "notch.obj")
    with open(path, "w") as f:
        f.write("v 0 0 0\nv 2 0 0\nv 2 2 0\nv 1 0.5 0\nv 0 2 0\nf 2 3 4 5 1\n")
    out = os.path.join(tmp, "copy.obj")
    summary, _ = run_json("reduce", path, "--keep", "100%", "-o", out)
    expect(summary["triangles_before"] == 3, f"{summary}")


def case_sphere_contour_passes(tmp):
    """A real contour does not overlap itself: sphere.vdb's reduces."""
    mesh = os.path.join(tmp, "sphere.obj")
    run("contour", data("sphere.vdb"), "-o", mesh)
    out = os.path.join(tmp, "small.obj")
    summary, _ = run_json("reduce", mesh, "--keep", "10%", "-o", out)
    expect(summary["parts_left_alone"] == 0 and summary["triangles_after"] <= summary["triangles_before"] // 10 + 1,
           f"{summary}")


def case_no_overlap(tmp):
    """headsq at 1150.5 to 10 %: the plain reduction's output crosses itself (so reducing it again is
    refused); with --no-overlap it does not, and reduces again with the same parts and genus."""
    vdb = os.path.join(tmp, "head.vdb")
    run("convert", data("headsq_64x64x93_u16le.raw"), "--dims", "64,64,93", "--type", "u16", "-o", vdb)
    mesh = os.path.join(tmp, "head.ply")
    run("contour", vdb, "--iso", "1150.5", "-q", "-o", mesh)
    plain = os.path.join(tmp, "plain.ply")
    summary, _ = run_json("reduce", mesh, "--keep", "10%", "-o", plain)
    expect(summary["refused"]["overlap"] == 0, f"the guard ran unasked: {summary['refused']}")
    expect_refused(tmp, ["reduce", plain, "-o", os.path.join(tmp, "again.ply")], plain,
                   "the mesh overlaps itself", ["head.vdb", "head.ply", "plain.ply"])
    guarded = os.path.join(tmp, "guarded.obj")
    summary, _ = run_json("reduce", mesh, "--keep", "10%", "--no-overlap", "-o", guarded)
    expect(summary["refused"]["overlap"] > 0, f"{summary['refused']}")
    expect(summary["triangles_after"] <= summary["triangles_before"] // 10 + 1, f"{summary}")
    again = os.path.join(tmp, "again.obj")
    second, _ = run_json("reduce", guarded, "--keep", "95%", "-o", again)
    expect(second["parts_left_alone"] == 0 and second["triangles_after"] < second["triangles_before"], f"{second}")
    points, _, faces, _ = base.read_ply(mesh)
    chi = euler(points, faces)
    for path in (guarded, again):
        points, _, faces = base.read_obj(path)
        base.check_closed(faces, len(points), path)
        expect(parts(faces) == summary["parts"], f"{path}: {parts(faces)} parts, the contour has {summary['parts']}")
        expect(euler(points, faces) == chi, f"{path}: Euler characteristic {euler(points, faces)}, the contour's {chi}")


def knot_rms(points, faces, reduced_points, reduced):
    """RMS, over the original vertices, of their height above the reduced graph (its triangle holding
    (x, y), linear): (5.41), computed here apart from the library."""
    total = 0.0
    for x, y, z in points:
        best, best_z = -1.0, None
        for f in reduced:
            (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = (reduced_points[v] for v in f)
            det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
            l1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / det
            l2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / det
            inside = min(1 - l1 - l2, l1, l2)
            if inside > best:
                best, best_z = inside, (1 - l1 - l2) * z0 + l1 * z1 + l2 * z2
        expect(best > -1e-6, f"({x}, {y}) lies outside the reduced graph's domain")
        total += (z - best_z) ** 2
    return (total / len(points)) ** 0.5


def projected_area(points, faces):
    """The signed (x, y) areas of the triangles: their sum, and the smallest."""
    areas = []
    for f in faces:
        (x0, y0, _), (x1, y1, _), (x2, y2, _) = (points[v] for v in f)
        areas.append(0.5 * ((x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)))
    return sum(areas), min(areas)


def case_graph(tmp):
    """--graph: the paraboloid over [-1, 1]^2 keeps its square domain, covered once, and reports the
    RMS height error at the original vertices as computed apart; --rms-tolerance stops before it;
    a graph turned over is refused by its first triangle."""
    mesh = os.path.join(tmp, "grid.obj")
    write_grid_obj(mesh, 41)
    points, _, faces = base.read_obj(mesh)
    out = os.path.join(tmp, "g10.obj")
    summary, _ = run_json("reduce", mesh, "--graph", "--keep", "10%", "-o", out)
    rp, _, rf = base.read_obj(out)
    expect(len(rf) == summary["triangles_after"] and len(rf) <= 320, f"{len(rf)} triangles, {summary}")
    area, smallest = projected_area(rp, rf)
    expect(abs(area - 4) < 1e-6 and smallest > 0, f"projected area {area}, smallest triangle {smallest}")
    rms = knot_rms(points, faces, rp, rf)
    expect(summary["graph_rms"] > 0 and abs(rms - summary["graph_rms"]) <= 1e-5 * rms,
           f"RMS height error {summary['graph_rms']}, computed apart {rms}")
    text = run("reduce", mesh, "--graph", "--keep", "10%", "-o", os.path.join(tmp, "text.obj")).stdout
    expect("RMS height error" in text, f"no RMS line in {text!r}")
    # Remark 5.10: stop before the RMS error exceeds half of what 10 % gave.
    limit = summary["graph_rms"] / 2
    bounded, _ = run_json("reduce", mesh, "--graph", "--keep", "10%", "--rms-tolerance", repr(limit), "-o", out)
    bp, _, bf = base.read_obj(out)
    expect(bounded["stop"] == "RMS tolerance reached" and len(bf) > 320, f"{bounded}")
    expect(bounded["graph_rms"] <= limit and knot_rms(points, faces, bp, bf) <= limit * (1 + 1e-5),
           f"RMS {bounded['graph_rms']} over the tolerance {limit}")
    proc = run("reduce", mesh, "--rms-tolerance", "0.1", "-o", out, code=2)
    expect("--graph" in proc.stderr, f"--rms-tolerance without --graph: {proc.stderr!r}")
    turned = os.path.join(tmp, "turned.obj")
    write_obj(turned, points, [(a, c, b) for a, b, c in faces])
    os.remove(out)
    expect_refused(tmp, ["reduce", turned, "--graph", "-o", out], turned,
                   "not a graph z = f(x, y): triangle 0 (vertices 0, 42, 1) does not turn counterclockwise "
                   "seen from +z", ["grid.obj", "turned.obj", "text.obj"])

def case_kernel_points(tmp):
    """headsq at 1150.5 to 1 %: where neither the fitted point nor a vertex of T sees the whole
    polygon, the centroid of its kernel often does. Without that point the same call stopped at
    7,688 triangles; with it the reduction goes on (6,700 measured), closed, same genus and parts."""
    vdb = os.path.join(tmp, "head.vdb")
    run("convert", data("headsq_64x64x93_u16le.raw"), "--dims", "64,64,93", "--type", "u16", "-o", vdb)
    mesh = os.path.join(tmp, "head.obj")
    run("contour", vdb, "--iso", "1150.5", "-q", "-o", mesh)
    points, _, faces = base.read_obj(mesh)
    out = os.path.join(tmp, "small.obj")
    summary, _ = run_json("reduce", mesh, "--keep", "1%", "-o", out)
    small_points, _, small = base.read_obj(out)
    base.check_closed(small, len(small_points), out)
    expect(summary["kernel_points"] > 500 and summary["vertex_points"] > 0, f"{summary}")
    expect(len(small) == summary["triangles_after"] < 7000, f"{len(small)} triangles, {summary}")
    expect(euler(small_points, small) == euler(points, faces), "Euler characteristic changed")
    expect(parts(small) == parts(faces), f"parts {parts(faces)} -> {parts(small)}")


GROUPS = {
    "reduce_cli": [case_help, case_keep_all_is_a_copy, case_single_triangle, case_bad_input, case_boundary,
                   case_overlap, case_manifold_parts, case_nan_ply, case_graph,
                   case_double_points_far_from_the_origin, case_concave_polygon],
    "reduce_contours": [case_cube_reduced_90, case_contour_reduce, case_keep_all_is_bit_identical,
                        case_curvature_in_the_file,
                        case_sphere_contour_passes, case_no_overlap, case_kernel_points],
}


if __name__ == "__main__":
    base.run_groups(GROUPS, sys.argv)
