#!/usr/bin/python3
"""The native module's curvature and Chapter 2 wrappers, no Blender.

usage: test_native_visual.py GROUP --cli ISOFORM --data DIR

Same conventions as test_native.py (whose helpers it uses): the library
comes from $ISOFORM_LIBRARY; figures are compared with the isoform command
on the same input, with analytic truth, and with the formulas of isoform.h.
"""
import json
import os
import sys
import tempfile

import numpy as np

import test_native as base
from test_native import expect, expect_raises
from isoform_blender import native, native_visualize as visual


def cli_json(*args):
    return json.loads(base.cli(*args, "--json").stdout)


def sphere_volume(radius_cells=20, spacing=0.05):
    """|x| sampled on a (2n+1)^3 lattice around the origin."""
    axis = np.arange(-radius_cells, radius_cells + 1) * spacing
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    distance = np.sqrt(x * x + y * y + z * z).astype(np.float32)
    origin = (-radius_cells * spacing,) * 3
    return native.Volume.from_dense(distance, spacing=(spacing,) * 3, origin=origin)


# ---------------------------------------------------------------- curvature

def case_sphere_curvature_is_one_over_r():
    """The contour |x| = 0.7 with outward normals (14 cells of radius): mean
    near 1/0.7 (median within 1 %, 90 % of the vertices within 6 %: the
    contour's own error), gauss near 1/0.49, every quantity copied."""
    with sphere_volume() as volume, volume.contour(0, isovalue=0.7,
                                                   orientation="increasing") as mesh:
        expect(not mesh.has_curvature, "curvature before isoform_curvature")
        stats = mesh.curvature()
        n = mesh.vertex_count
        expect(mesh.has_curvature and stats.vertices == n and stats.failed == 0,
               f"stats {stats}")
        mean = mesh.curvature_values("mean")
        expect(mean.shape == (n,) and mean.dtype == np.float32, f"mean {mean.shape}")
        near = np.mean(np.abs(mean * 0.7 - 1.0) < 0.06)
        expect(near > 0.9 and abs(np.median(mean) * 0.7 - 1) < 0.01,
               f"{near:.1%} of the vertices have mean within 6% of 1/r, median {np.median(mean)}")
        gauss = np.median(mesh.curvature_values("gauss"))
        expect(abs(gauss * 0.49 - 1.0) < 0.03, f"median gauss {gauss}")
        k1, k2 = mesh.curvature_values("k1"), mesh.curvature_values("k2")
        expect(np.all(k1 >= k2), "k1 < k2 somewhere")
        expect(np.allclose(mesh.curvature_values("absolute"), np.abs(k1) + np.abs(k2), atol=1e-5),
               "absolute is not |k1| + |k2|")
        d1, d2 = mesh.curvature_values("d1"), mesh.curvature_values("d2")
        expect(d1.shape == (n, 3) and np.allclose(np.linalg.norm(d1, axis=1), 1, atol=1e-4),
               "d1 not unit vectors")
        expect(np.all(np.abs(np.einsum("ij,ij->i", d1, d2)) < 1e-3), "d1 not orthogonal to d2")
        expect(mesh.curvature_flags().shape == (n,), "flags")
        colors = mesh.colors()
        expect(colors is not None and colors.shape == (n, 4) and np.all(colors[:, 3] == 255),
               "colours")


def case_curvature_matches_cli():
    """The same PLY through the binding and through `isoform curvature`."""
    with tempfile.TemporaryDirectory() as tmp:
        path, out = os.path.join(tmp, "sphere.ply"), os.path.join(tmp, "curved.ply")
        with sphere_volume() as volume, volume.contour(0, isovalue=0.7,
                                                       orientation="increasing") as mesh:
            mesh.save(path)
        summary = cli_json("curvature", path, "-o", out, "--method", "cubic", "--color-by",
                           "gauss")["curvature"]
        with native.Mesh.load(path) as mesh:
            stats = mesh.curvature(method="cubic", color_by="gauss")
            values = {q: mesh.curvature_values(q) for q in native.CURVATURE_QUANTITIES}
    expect(stats.vertices == summary["vertices"] and stats.method == 2, f"stats {stats}")
    expect(np.isclose(stats.color_min, summary["colors"]["min"]) and
           np.isclose(stats.color_max, summary["colors"]["max"]), f"colour range {stats}")
    for quantity, array in values.items():
        for key, got in (("min", array.min()), ("max", array.max()),
                         ("p50", np.percentile(array, 50, method="lower"))):
            expect(abs(got - summary[quantity][key]) < 1e-5 * max(1, abs(got)),
                   f"{quantity} {key}: binding {got}, CLI {summary[quantity][key]}")


def case_curvature_from_f64_arrays_and_errors():
    """A tetrahedron from double points: every vertex gets a finite value;
    an unknown method or quantity is refused before the library is called;
    a mesh without curvature refuses its copy-out with the library's message."""
    points = base.TETRA_POINTS.astype(np.float64)
    with native.Mesh.from_arrays_f64(points, base.TETRA_TRIANGLES) as mesh:
        expect(np.array_equal(mesh.points(), base.TETRA_POINTS), "points")
        expect_raises(native.IsoformError, lambda: mesh.curvature_values("mean"), "curvature")
        stats = mesh.curvature(method="seed")
        expect(stats.vertices == 4 and stats.method == 0, f"stats {stats}")
        expect(np.all(np.isfinite(mesh.curvature_values("k1"))), "non-finite curvature")
        expect_raises(ValueError, lambda: mesh.curvature(method="quintic"), "quintic")
        expect_raises(ValueError, lambda: mesh.curvature_values("k3"), "k3")


# ---------------------------------------------------------------- visualisation

def linear_volume(n=10):
    """f = x on the lattice 0..n-1 (spacing 1, origin 0)."""
    values = np.broadcast_to(np.arange(n, dtype=np.float32), (n, n, n))
    return native.Volume.from_dense(values, spacing=(1, 1, 1), origin=(0, 0, 0))


def case_slice_image_values_are_trilinear():
    """f = x, slice z = 0.5 at 10 samples: pixel column c holds x = c, every row."""
    with linear_volume() as volume, visual.slice_image(volume, 0, 2, resolution=10,
                                                       colour_bar=False) as image:
        values = image.values()
        expect((image.width, image.height) == (10, 10), f"{image.width}x{image.height}")
        expect(np.allclose(values, np.arange(10)[None, :], atol=1e-5), f"values {values[0]}")
        expect(image.value_range() == (0.0, 9.0), f"range {image.value_range()}")
        rgba = image.rgba()
        expect(rgba.shape == (10, 10, 4) and np.all(rgba[:, 0] == rgba[0, 0]) and
               not np.array_equal(rgba[0, 0], rgba[0, 9]), "colours do not follow x")
    with linear_volume() as volume, visual.slice_image(volume, 0, 2, resolution=10) as image:
        expect(image.width > 10 and np.isnan(image.values()[:, 10:]).all(), "no colour bar")


def case_slice_mesh_plane_positions():
    """Three planes of smoke.vdb: the x plane lies at x_min + 0.3 (x_max - x_min)."""
    with native.Volume.open(base.data("smoke.vdb")) as volume:
        with visual.slice_mesh(volume, "density", 0, position=(0.3, 0.5, 0.5),
                               resolution=16) as mesh:
            points, triangles = mesh.points(), mesh.triangles()
            edges, colours = mesh.edges(), mesh.colors()
    used = np.unique(triangles)
    low, high = points.min(axis=0), points.max(axis=0)  # the box edges reach the domain
    expect(np.allclose(points[used, 0], low[0] + 0.3 * (high[0] - low[0]), atol=1e-4),
           f"plane x in {points[used, 0].min()}..{points[used, 0].max()}")
    expect(len(edges) == 12, f"{len(edges)} domain box edges")
    expect(colours.shape == (len(points), 4) and np.all(colours[:, 3] == 255), "colours")
    expect_raises(native.IsoformError, lambda: visual.slice_mesh(
        native.Volume.open(base.data("smoke.vdb")), "", 0, position=(1.5, 0.5, 0.5)), "1.5")


def case_boxes_match_cli_and_formula():
    """q = 2,3,1 with 2x1 face cells: 6 q k l quads, (k+1)(l+1) points per face."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "boxes.ply")
        summary = cli_json("boxes", base.data("smoke.vdb"), "--q", "2,3,1", "--face-cells", "2,1",
                           "-o", out)
        with native.Volume.open(base.data("smoke.vdb")) as volume:
            arrays = visual.coloured_arrays(visual.boxes(volume, "", q=(2, 3, 1), gap=1.0,
                                                         face_cells=(2, 1)))
        with native.Mesh.load(out) as loaded:
            cli_points = loaded.points()
    boxes = 2 * 3 * 1
    expect(len(arrays.triangles) == 2 * 6 * boxes * 2 == summary["mesh"]["triangles"],
           f"{len(arrays.triangles)} triangles, CLI {summary['mesh']}")
    expect(len(arrays.points) == 6 * boxes * 3 * 2 == summary["mesh"]["vertices"],
           f"{len(arrays.points)} vertices")
    expect(np.array_equal(arrays.points, cli_points), "points differ from the CLI's PLY")
    expect(arrays.colors is not None and len(arrays.edges) == 0, "colours or edges")
    expect_raises(native.IsoformError, lambda: visual.boxes(
        native.Volume.open(base.data("smoke.vdb")), "", q=(0, 1, 1)), "q")


def case_stack_counts_alpha_and_order():
    """n = 2,3,4: 3 n_x n_y n_z + n_x n_y + n_x n_z + n_y n_z rectangles,
    alpha 1 - t, nearest corners' depth along view never increasing."""
    view = np.array([-1.0, -0.5, -2.0])
    with native.Volume.open(base.data("smoke.vdb")) as volume:
        arrays = visual.coloured_arrays(visual.stack(volume, "", n=(2, 3, 4), transparency=0.75,
                                                     view=view))
    rectangles = 3 * 24 + 6 + 8 + 12
    expect(len(arrays.triangles) == 2 * rectangles and len(arrays.points) == 4 * rectangles,
           f"{len(arrays.triangles)} triangles {len(arrays.points)} points")
    expect(np.all(arrays.colors[:, 3] == round(255 * 0.25)), f"alpha {set(arrays.colors[:, 3])}")
    corners = arrays.points[arrays.triangles.reshape(rectangles, 6)]
    nearest = (corners @ (view / np.linalg.norm(view))).min(axis=1)
    expect(np.all(np.diff(nearest) <= 1e-4), "rectangles not back to front")
    expect_raises(native.IsoformError, lambda: visual.stack(
        native.Volume.open(base.data("smoke.vdb")), "", view=(0, 0, 0)), "view")


def case_visual_errors_name_the_input():
    with tempfile.TemporaryDirectory() as tmp:
        vector = base.vector_vdb(tmp)
        with native.Volume.open(vector) as volume:
            expect_raises(native.IsoformError, lambda: visual.slice_mesh(volume, ""),
                          "no scalar grid", "velocity")
            expect_raises(native.IsoformError, lambda: visual.boxes(volume, "velocity"),
                          "velocity", "not a scalar grid")
    expect_raises(ValueError, lambda: visual.slice_mesh(
        native.Volume.open(base.data("smoke.vdb")), "", colour_map="jet"), "jet")


GROUPS = {
    "curvature": [case_sphere_curvature_is_one_over_r, case_curvature_matches_cli,
                  case_curvature_from_f64_arrays_and_errors],
    "visualize": [case_slice_image_values_are_trilinear, case_slice_mesh_plane_positions,
                  case_boxes_match_cli_and_formula, case_stack_counts_alpha_and_order,
                  case_visual_errors_name_the_input],
}


def main():
    return base.run_groups(GROUPS, ("--cli", "--vector-vdb-maker", "--data"))


if __name__ == "__main__":
    sys.exit(main())
