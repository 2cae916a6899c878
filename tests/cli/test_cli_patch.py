"""The `isoform patch` command (Chapter 6 side-vertex surface), run as a
program: exact counts and the sphere property on Figure 6.7's tetrahedron, a
watertight tessellation of a real contour, estimated normals, options, and
bad input. Shares test_cli.py's helpers.

Usage: test_cli_patch.py ISOFORM_BINARY SHARED_DATA_DIR GROUP"""
import math
import os
import sys

import test_cli as base
from test_cli import expect, run, run_json, data, leftovers, expect_failure, check_ply_mesh


def write_tetrahedron_obj(path, with_normals=True):
    s = 1 / math.sqrt(3)
    points = [(s, s, s), (s, -s, -s), (-s, s, -s), (-s, -s, s)]
    faces = [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]
    with open(path, "w") as f:
        for p in points:
            f.write("v %.17g %.17g %.17g\n" % p)
            if with_normals:
                f.write("vn %.17g %.17g %.17g\n" % p)
        for a, b, c in faces:
            if with_normals:
                f.write(f"f {a + 1}//{a + 1} {b + 1}//{b + 1} {c + 1}//{c + 1}\n")
            else:
                f.write(f"f {a + 1} {b + 1} {c + 1}\n")


def radius(p):
    return math.sqrt(sum(c * c for c in p))


def case_help(tmp):
    proc = run("patch", "--help")
    for option in ["--level", "--blend", "--tension", "--output", "--progress", "--quiet", "--json"]:
        expect(option in proc.stdout, f"isoform patch --help does not mention {option}")
    expect("patch" in run("--help").stdout, "isoform --help does not list patch")


def case_tetrahedron(tmp):
    """Figure 6.7 data: 4 * 4^2 triangles, 4 + 6*3 + 4*3 vertices; every
    vertex on a mesh edge lies on the unit sphere, every interior one inside."""
    mesh = os.path.join(tmp, "tetra.obj")
    write_tetrahedron_obj(mesh)
    out = os.path.join(tmp, "smooth.ply")
    summary, proc = run_json("patch", mesh, "--level", "2", "-o", out)
    expect(not summary["normals_estimated"] and "normals" not in proc.stderr, f"{summary} {proc.stderr}")
    points, normals, faces, _ = check_ply_mesh(out, summary["mesh"])
    expect(len(faces) == 64 and len(points) == 34, f"{len(points)} vertices, {len(faces)} triangles")
    on_sphere = sum(1 for p in points if abs(radius(p) - 1) < 1e-6)
    inside = sum(1 for p in points if radius(p) < 1 - 1e-3)
    expect(on_sphere == 22 and inside == 12, f"{on_sphere} vertices on the sphere, {inside} inside")
    # Exact normals: on the edges they are the sphere's.
    for p, n in zip(points, normals):
        if abs(radius(p) - 1) < 1e-6:
            expect(sum(a * b for a, b in zip(p, n)) > 1 - 1e-5, f"normal {n} at {p}")
    expect(summary["patch"]["edges"] == 6 and summary["patch"]["nonconvex_edges"] == 0, f"{summary['patch']}")
    # Lower weights pull the surface in; the printed blend is accepted.
    low = os.path.join(tmp, "low.ply")
    run("patch", mesh, "--level", "2", "--tension", "0.2", "--blend", "printed", "-o", low)
    low_points, _, low_faces, _ = check_ply_mesh(low)
    expect(len(low_faces) == 64, f"{len(low_faces)} triangles")
    expect(max(radius(p) for p in low_points) < 1 + 1e-6, "a lower weight left the sphere")
    expect(sorted(radius(p) for p in low_points)[10] < sorted(radius(p) for p in points)[10] - 0.05,
           "a lower weight did not pull the surface toward the tetrahedron")
    expect(sorted(leftovers(tmp, [])) == ["low.ply", "smooth.ply", "tetra.obj"], f"left {leftovers(tmp, [])}")


def case_estimated_normals(tmp):
    mesh = os.path.join(tmp, "tetra.obj")
    write_tetrahedron_obj(mesh, with_normals=False)
    out = os.path.join(tmp, "smooth.obj")
    proc = run("patch", mesh, "--level", "1", "-o", out)
    expect("no vertex normals" in proc.stderr and "estimated" in proc.stderr, f"stderr: {proc.stderr}")
    expect("normals estimated" in proc.stdout, f"stdout: {proc.stdout}")
    points, normal_count, faces = base.read_obj(out)
    base.check_closed(faces, len(points), out)
    expect(len(faces) == 16 and normal_count == len(points), f"{len(faces)} faces, {normal_count} normals")
    quiet = run("patch", mesh, "--level", "1", "--quiet", "-o", out)
    expect(quiet.stderr == "", f"--quiet printed {quiet.stderr}")


def case_sphere_contour(tmp):
    """A real contour (sphere.vdb, radius 3): the tessellation is closed,
    manifold and outward, its radii spread no more than the contour's, and
    its exact normals are radial."""
    mesh = os.path.join(tmp, "sphere.ply")
    run("contour", data("sphere.vdb"), "-o", mesh)
    contour_points, _, contour_faces, _ = base.read_ply(mesh)
    out = os.path.join(tmp, "smooth.ply")
    summary, _ = run_json("patch", mesh, "--level", "1", "-o", out)
    points, normals, faces, _ = check_ply_mesh(out, summary["mesh"])
    expect(len(faces) == 4 * len(contour_faces), f"{len(faces)} triangles from {len(contour_faces)}")
    expect(summary["mesh"]["euler_characteristic"] == 2 and summary["mesh"]["parts"] == 1, f"{summary['mesh']}")
    r0 = [radius(p) for p in contour_points]
    r1 = [radius(p) for p in points]
    spread0, spread1 = max(r0) - min(r0), max(r1) - min(r1)
    expect(spread1 < spread0 + 0.01, f"the patch's radii spread {spread1}, the contour's {spread0}")
    # NOTE: not all: edges of 1/700 voxel (the contour's crossings held off
    # samples) cut steeply through the tangent planes and make S-shaped
    # conics whose normals turn by tens of degrees over 7e-5 world units.
    cos1 = math.cos(math.radians(1.0))
    within = sum(1 for p, n in zip(points, normals) if sum(a * b for a, b in zip(p, n)) > cos1 * radius(p))
    expect(within > 0.99 * len(points), f"only {within} of {len(points)} normals within 1 degree of radial")
    inward = sum(1 for p, n in zip(points, normals) if sum(a * b for a, b in zip(p, n)) < 0)
    expect(inward == 0, f"{inward} normals point into the sphere")


def case_bad_input(tmp):
    mesh = os.path.join(tmp, "empty.ply")
    with open(mesh, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n"
                "0 0 0\n1 0 0\n0 1 0\n")
    out = os.path.join(tmp, "out.ply")
    expect_failure(tmp, ["patch", mesh, "-o", out], ["empty.ply", "no triangles"], ["empty.ply"])
    expect_failure(tmp, ["patch", os.path.join(tmp, "missing.ply"), "-o", out], ["missing.ply"], ["empty.ply"])
    expect_failure(tmp, ["patch", mesh, "-o", mesh], ["empty.ply"], ["empty.ply"])
    expect_failure(tmp, ["patch", mesh, "--tension", "soft", "-o", out], ["--tension", "soft"], ["empty.ply"])
    expect_failure(tmp, ["patch", mesh, "--tension", "-1", "-o", out], ["--tension"], ["empty.ply"])
    # A triangle with a repeated vertex is named.
    bad = os.path.join(tmp, "bad.obj")
    with open(bad, "w") as f:
        f.write("v 0 0 0\nvn 0 0 1\nv 1 0 0\nvn 0 0 1\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//3\nf 1//1 1//1 2//2\n")
    expect_failure(tmp, ["patch", bad, "-o", out], ["bad.obj", "triangle 1"], ["empty.ply", "bad.obj"])
    run("patch", mesh, "--level", "11", "-o", out, code=2)


GROUPS = {
    "patch_help": [case_help],
    "patch_tetrahedron": [case_tetrahedron, case_estimated_normals],
    "patch_sphere": [case_sphere_contour],
    "patch_bad_input": [case_bad_input],
}


if __name__ == "__main__":
    base.run_groups(GROUPS, sys.argv)
