#!/usr/bin/python3
"""The native module's reduction (Chapter 5) and side-vertex surface
(Chapter 6) wrappers, no Blender.

usage: test_native_surface.py GROUP --cli ISOFORM --vector-vdb-maker X --data DIR

Same conventions as test_native.py (whose helpers it uses): the library
comes from $ISOFORM_LIBRARY; figures are checked against the isoform command
on the same input and against what isoform.h promises.
"""
import os
import sys
import tempfile

import numpy as np

import test_native as base
from test_native import expect, expect_raises
from test_native_visual import sphere_volume
from thin_shell import thin_shell
from height_field import paraboloid_grid, projected_areas
from isoform_blender import native, native_surface as surface


def sphere_contour():
    """|x| = 0.7 on a 41^3 lattice, outward normals: a closed genus-0 mesh."""
    with sphere_volume() as volume:
        return volume.contour(0, isovalue=0.7, orientation="increasing")


# ---------------------------------------------------------------- reduce

def case_reduce_keeps_the_fraction_and_the_topology():
    """10% of the sphere contour's triangles stay; it stays closed, manifold
    and of Euler characteristic 2, every vertex near the sphere."""
    with sphere_contour() as mesh:
        before = mesh.triangle_count
        stats = surface.reduce(mesh, keep_fraction=0.1)
        after = mesh.stats()
        expect(stats.triangles_before == before and stats.triangles_after == mesh.triangle_count,
               f"stats {stats} for {before} -> {mesh.triangle_count}")
        expect(abs(mesh.triangle_count - 0.1 * before) <= 2,
               f"{mesh.triangle_count} triangles left of {before}")
        expect(after.boundary_edges == 0 and after.nonmanifold_edges == 0 and
               after.euler_characteristic == 2 and after.parts == 1, f"mesh stats {after}")
        # New points move to the least-squares best place for the original
        # vertices, off the sphere by a fraction of the larger triangles' sagitta.
        radius = np.linalg.norm(mesh.points(), axis=1)
        expect(np.all(np.abs(radius - 0.7) < 0.025) and np.sqrt(np.mean((radius - 0.7) ** 2)) < 0.01,
               f"radius {radius.min()}..{radius.max()}")


def case_reduce_matches_cli():
    """The CLI on the same mesh, saved and read back, keeps as many triangles."""
    with tempfile.TemporaryDirectory() as tmp, sphere_contour() as mesh:
        source, out = os.path.join(tmp, "sphere.ply"), os.path.join(tmp, "reduced.ply")
        mesh.save(source)
        with native.Mesh.load(source) as loaded:
            surface.reduce(loaded, keep_fraction=0.25)
            expected = loaded.triangle_count
        base.cli("reduce", source, "--keep", "25%", "-o", out)
        with native.Mesh.load(out) as reduced:
            expect(reduced.triangle_count == expected,
                   f"CLI kept {reduced.triangle_count} triangles, the module {expected}")


def case_reduce_errors():
    """A keep fraction outside (0, 1] and a non-manifold mesh are refused with
    the library's message; the mesh is left as it was."""
    with sphere_contour() as mesh:
        count = mesh.triangle_count
        expect_raises(native.IsoformError, lambda: surface.reduce(mesh, keep_fraction=0.0),
                      "keep")
        expect(mesh.triangle_count == count, "a refused reduction changed the mesh")
    fin = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], dtype=np.float32)
    with native.Mesh.from_arrays(fin, [[0, 1, 2], [1, 0, 3], [0, 1, 4]]) as mesh:
        expect_raises(native.IsoformError, lambda: surface.reduce(mesh), "edge")
        expect(mesh.triangle_count == 3, "the non-manifold mesh was changed")


def case_reduce_prevent_overlap():
    """A thin torus shell reduced to 2%: unguarded, its sheets cross (reducing
    the result again is refused); with prevent_overlap they do not (it reduces
    again), the guard refused removals, and the shell stays two closed parts."""
    points, triangles = thin_shell()
    with native.Mesh.from_arrays_f64(points, triangles) as mesh:
        stats = surface.reduce(mesh, keep_fraction=0.02)
        expect(stats.refused_overlap == 0, f"the guard ran unasked: {stats}")
        expect_raises(native.IsoformError, lambda: surface.reduce(mesh, keep_fraction=0.5),
                      "overlaps itself")
    with native.Mesh.from_arrays_f64(points, triangles) as mesh:
        stats = surface.reduce(mesh, keep_fraction=0.02, prevent_overlap=True)
        expect(stats.refused_overlap > 0 and stats.removals > 1000, f"stats {stats}")
        surface.reduce(mesh, keep_fraction=0.5)
        after = mesh.stats()
        expect(after.boundary_edges == 0 and after.nonmanifold_edges == 0 and after.parts == 2 and
               after.euler_characteristic == 0, f"mesh stats {after}")


def case_reduce_height_field():
    """height_field on the paraboloid over [-1, 1]^2 reduced to 10%: the
    square stays covered once (every triangle counterclockwise, areas summing
    to 4), the RMS height error is reported; turned over, the mesh is refused
    by its first triangle and left as it was."""
    points, triangles = paraboloid_grid(41)
    with native.Mesh.from_arrays_f64(points, triangles) as mesh:
        stats = surface.reduce(mesh, keep_fraction=0.1, height_field=True)
        areas = projected_areas(mesh.points(), mesh.triangles())
        expect(mesh.triangle_count <= 320 and areas.min() > 0 and abs(areas.sum() - 4) < 1e-5,
               f"{mesh.triangle_count} triangles, smallest area {areas.min()}, sum {areas.sum()}")
        expect(0 < stats.graph_rms < 0.01, f"RMS height error {stats.graph_rms}")
    with native.Mesh.from_arrays_f64(points, triangles[:, [0, 2, 1]]) as mesh:
        expect_raises(native.IsoformError, lambda: surface.reduce(mesh, height_field=True),
                      "not a graph z = f(x, y): triangle 0 ")
        expect(mesh.triangle_count == len(triangles), "the refused mesh was changed")


# ---------------------------------------------------------------- patch

def case_patch_interpolates_and_tessellates():
    """At each triangle's corners the surface is the vertex with its normal;
    level 2 gives 16 triangles per triangle, closed, normals unit."""
    with sphere_contour() as mesh, surface.Patch.create(mesh) as patch:
        points, normals, triangles = mesh.points(), mesh.normals(), mesh.triangles()
        corners = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
        which = np.repeat(np.arange(len(triangles), dtype=np.int32), 3)
        at, n = patch.evaluate(which, np.tile(corners, (len(triangles), 1)))
        vertex = triangles.ravel()
        expect(np.abs(at - points[vertex]).max() < 1e-6, "corners are not the vertices")
        expect(np.abs(n - normals[vertex]).max() < 1e-5, "corner normals are not the vertex's")
        stats = patch.stats()
        expect(stats.triangles == len(triangles), f"patch stats {stats}")
        with patch.tessellate(2) as smooth:
            expect(smooth.triangle_count == 16 * len(triangles), f"{smooth.triangle_count}")
            facts = smooth.stats()
            expect(facts.boundary_edges == 0 and facts.nonmanifold_edges == 0 and
                   facts.euler_characteristic == 2, f"tessellation stats {facts}")
            expect(np.allclose(np.linalg.norm(smooth.normals(), axis=1), 1.0, atol=1e-5),
                   "normals not unit")


def case_patch_errors_name_the_sample():
    """A triangle index out of range and (u, v) outside the triangle are
    refused; the library's message names the sample."""
    with sphere_contour() as mesh, surface.Patch.create(mesh) as patch:
        bad = np.array([mesh.triangle_count], dtype=np.int32)
        expect_raises(native.IsoformError, lambda: patch.evaluate(bad, [[0.2, 0.2]]), "0")
        expect_raises(native.IsoformError,
                      lambda: patch.evaluate(np.zeros(2, np.int32), [[0.2, 0.2], [0.9, 0.9]]),
                      "1")
        expect_raises(ValueError, lambda: patch.evaluate(np.zeros(2, np.int32), [[0.2, 0.2]]),
                      "pairs")


# ---------------------------------------------------------------- compare

def case_compare_loop_against_side_vertex():
    """The sphere contour reduced to 600 triangles, new points kept on their
    fitted surfaces, against the fitted sphere: the side-vertex surface
    passes through the vertices, Loop's limit does not; the side-vertex
    surface is far closer to the sphere than the flat triangles, Loop (which
    shrinks convex data) is not; the Loop tessellation has level^2 triangles
    per base triangle and is closed."""
    with sphere_contour() as mesh:
        surface.reduce(mesh, keep_fraction=600 / mesh.triangle_count, on_surface=True)
        result = surface.compare(mesh, level=4, reference="sphere")
        metrics = result["metrics"]
        expect(set(metrics) == {"linear", "loop", "side-vertex"}, f"surfaces {sorted(metrics)}")
        expect(result["unit"] == "world units", f"unit {result['unit']!r}")
        side, loop, flat = metrics["side-vertex"], metrics["loop"], metrics["linear"]
        expect(side["data_point_error"]["max"] < 1e-6, f"side-vertex {side['data_point_error']}")
        expect(loop["data_point_error"]["max"] > 1e-4, f"loop {loop['data_point_error']}")
        expect(side["deviation"]["rms"] < flat["deviation"]["rms"] / 5,
               f"side-vertex deviation {side['deviation']} vs flat {flat['deviation']}")
        expect(loop["deviation"]["rms"] > flat["deviation"]["rms"],
               f"loop deviation {loop['deviation']} vs flat {flat['deviation']}")
        arrays = result["tessellations"]["loop"]
        expect(len(arrays.triangles) == 16 * mesh.triangle_count and arrays.stats.boundary_edges == 0,
               f"loop tessellation {len(arrays.triangles)} triangles, {arrays.stats}")


GROUPS = {
    "reduce": [case_reduce_keeps_the_fraction_and_the_topology, case_reduce_matches_cli,
               case_reduce_errors, case_reduce_prevent_overlap,
               case_reduce_height_field],
    "patch": [case_patch_interpolates_and_tessellates, case_patch_errors_name_the_sample,
              case_compare_loop_against_side_vertex],
}


def main():
    return base.run_groups(GROUPS, ("--cli", "--vector-vdb-maker", "--data"))


if __name__ == "__main__":
    sys.exit(main())
