"""Reduction (Chapter 5) and the side-vertex surface (Chapter 6) through
ctypes, without bpy: isoform.h "Reduction" and "Side-vertex surface".

Options are keyword arguments; what is not given keeps the library's default
(isoform_*_options_default).
"""
import ctypes

import numpy as np

from . import native
from . import native_structs as structs
from .native_signatures import _f64, _i32

REDUCE_POINTS = {"quadratic": 0, "quadric": 1}
PATCH_BLENDS = {"printed": 0, "squared": 1}


def reduce_options(keep_fraction=None, tolerance=None, lock_boundary=None, point=None,
                   on_surface=None, prevent_overlap=None, height_field=None):
    """on_surface: keep each new point on its fitted surface (the seed's point)
    instead of the least-squares best place; for the side-vertex surface,
    which interpolates the vertices. prevent_overlap: refuse a removal whose
    new triangles would cross the rest of the mesh (slower; for thin walls
    and close sheets). height_field: the mesh is a graph z = f(x, y), every
    triangle counterclockwise seen from +z (the library's graph mode; the
    stats' graph_rms is the RMS height error at the original vertices)."""
    lib = native.library()
    options = structs.ReduceOptions()
    lib.reduce_options_default(ctypes.byref(options))
    if keep_fraction is not None:
        options.keep_fraction = float(keep_fraction)
    if tolerance is not None:
        options.tolerance = float(tolerance)
    if lock_boundary is not None:
        options.lock_boundary = 1 if lock_boundary else 0
    if point is not None:
        options.point_method = native._choice(REDUCE_POINTS, point, "replacement point")
    if on_surface is not None:
        options.refine_point = 0 if on_surface else 1
    if prevent_overlap is not None:
        options.prevent_overlap = 1 if prevent_overlap else 0
    if height_field is not None:
        options.graph = 1 if height_field else 0
    return options


def reduce(mesh, progress=None, **settings):
    """Reduces mesh (a native.Mesh) in place by iterative triangle removal;
    returns the reduction's stats as a namespace."""
    lib = native.library()
    options = reduce_options(**settings)
    lib.check(lib.reduce(mesh.handle, ctypes.byref(options), native._progress_pointer(progress)))
    stats = structs.ReduceStats()
    lib.check(lib.mesh_reduce_stats(mesh.handle, ctypes.byref(stats)))
    return native._struct_namespace(stats)


def patch_options(blend=None, tension=None):
    lib = native.library()
    options = structs.PatchOptions()
    lib.patch_options_default(ctypes.byref(options))
    if blend is not None:
        options.blend = native._choice(PATCH_BLENDS, blend, "blend")
    if tension is not None:
        options.tension = float(tension)
    return options


class Patch(native._Handle):
    """An isoform_patch: the side-vertex surface over a mesh with normals."""
    _free_name = "patch_free"

    @classmethod
    def create(cls, mesh, **settings):
        options = patch_options(**settings)
        return native._make(cls, lambda lib, out: lib.patch_create(
            mesh.handle, ctypes.byref(options), out))

    def stats(self):
        out = structs.PatchStats()
        self._lib.check(self._lib.patch_stats_get(self.handle, ctypes.byref(out)))
        return native._struct_namespace(out)

    def evaluate(self, triangles, uv):
        """Points and exact unit normals, (k, 3) float64 each, at triangle
        triangles[k] and barycentric (u, v) = uv[k]."""
        t = np.ascontiguousarray(triangles, dtype=np.int32).ravel()
        p = native._as_c(uv, np.float64, 2)
        if p.shape[0] != t.shape[0]:
            raise ValueError(f"{t.shape[0]} triangles but {p.shape[0]} (u, v) pairs")
        points = np.empty((t.shape[0], 3), dtype=np.float64)
        normals = np.empty((t.shape[0], 3), dtype=np.float64)
        self._lib.check(self._lib.patch_evaluate(
            self.handle, t.shape[0], t.ctypes.data_as(_i32), p.ctypes.data_as(_f64),
            points.ctypes.data_as(_f64), normals.ctypes.data_as(_f64)))
        return points, normals

    def tessellate(self, level, progress=None):
        """A new native.Mesh: every triangle split into 4**level, exact normals."""
        return native._make(native.Mesh, lambda lib, out: lib.patch_tessellate(
            self.handle, int(level), native._progress_pointer(progress), out))


REFERENCES = {"none": 0, "sphere": 1, "torus": 2}


def compare_options(level=None, reference=None, input_name=None):
    lib = native.library()
    options = structs.CompareOptions()
    lib.compare_options_default(ctypes.byref(options))
    if level is not None:
        options.level = int(level)
    if reference is not None:
        options.reference = native._choice(REFERENCES, reference, "reference")
    options.table_triangles = 0
    if input_name is not None:
        options.input_name = str(input_name).encode("utf-8")
    return options


def _plain(value):
    """A ctypes struct (nested ones too) as a dict of Python numbers."""
    if isinstance(value, ctypes.Structure):
        return {name: _plain(getattr(value, name)) for name, _ in value._fields_}
    return value


def compare(mesh, progress=None, tessellations=("loop",), **settings):
    """Measures the surfaces over mesh (linear, loop, the side-vertex one)
    at the same samples (isoform_compare). Returns a dict: reference, unit,
    metrics {surface name: nested dict of isoform_compare_metrics} and
    tessellations {name: native.MeshArrays} for the names asked for."""
    lib = native.library()
    options = compare_options(**settings)
    report = ctypes.c_void_p()
    lib.check(lib.compare(mesh.handle, None, ctypes.byref(options),
                          native._progress_pointer(progress), ctypes.byref(report)))
    try:
        result = {"reference": lib.compare_report_reference(report).decode("utf-8"),
                  "unit": lib.compare_report_deviation_unit(report).decode("utf-8"),
                  "metrics": {}, "tessellations": {}}
        for index in range(lib.compare_report_surface_count(report)):
            name = lib.compare_report_surface_name(report, index).decode("utf-8")
            metrics = structs.CompareMetrics()
            lib.check(lib.compare_report_metrics(report, index, ctypes.byref(metrics)))
            result["metrics"][name] = _plain(metrics)
            if name in tessellations:
                tessellation = ctypes.c_void_p()
                lib.check(lib.compare_report_tessellation(report, index,
                                                          ctypes.byref(tessellation)))
                with native.Mesh(lib, tessellation.value) as surface:
                    result["tessellations"][name] = surface.arrays()
        return result
    finally:
        lib.compare_report_free(report)
