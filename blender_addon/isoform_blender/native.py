"""The isoform C API (libcore/isoform.h) through ctypes, without bpy.

Usable from any Python with numpy: the add-on's operators call it, and
tests/blender/test_native.py runs it from /usr/bin/python3.

- The library is looked up beside this file first (the installed add-on
  carries libisoform.so in its folder), then at $ISOFORM_LIBRARY (tests, a
  development build). It is loaded once; a library whose isoform_version()
  differs from ISOFORM_VERSION below is refused before any other symbol is
  touched.
- Every function used has its argtypes and restype declared (the C parameter
  names are in the comments of _SIGNATURES).
- A failed call raises IsoformError carrying isoform_last_error(). The
  message is thread-local in the library, so it is read on the thread that
  made the call, right after it (worker threads get their own messages).
- Bulk data goes out through caller-owned numpy buffers (np.empty of the
  exact dtype, C-contiguous) and in through np.ascontiguousarray; no
  per-element Python loops.
- ctypes releases the GIL during a call: a contour can run on a worker thread
  while the caller polls a Progress.
"""
import ctypes
import os
import threading
from types import SimpleNamespace

import numpy as np

from . import native_structs as structs
from .native_signatures import SIGNATURES as _SIGNATURES
from .native_signatures import _f32, _f64, _i32, _u8

# Must equal ISOFORM_VERSION of the isoform.h this module mirrors
# (major * 10000 + minor * 100 + patch).
ISOFORM_VERSION = 300
LIBRARY_FILE = "libisoform.so"
LIBRARY_ENV = "ISOFORM_LIBRARY"

STATUS_CANCELLED = 6

CLASS_OTHER, CLASS_LEVEL_SET, CLASS_FOG = 0, 1, 2
METHODS = {"cells": 0, "tetra": 1}
ORIENTATIONS = {"auto": 0, "increasing": 1, "decreasing": 2}
CURVATURE_METHODS = {"seed": 0, "quadric": 1, "cubic": 2, "quartic": 3}
# The scalar quantities, by their attribute names; d1, d2 are directions.
CURVATURE_QUANTITIES = {"k1": 0, "k2": 1, "mean": 2, "gauss": 3, "absolute": 4}
CURVATURE_DIRECTIONS = {"d1": 5, "d2": 6}
STAGE_NAMES = {0: "idle", 1: "loading", 2: "contouring", 3: "merging", 4: "topology", 5: "done",
               6: "curvature", 8: "reduction", 10: "smooth surface", 16: "comparison"}


class LibraryError(Exception):
    """libisoform cannot be found or loaded, or is not the expected one."""


class VersionMismatch(LibraryError):
    """The library found reports a different ISOFORM_VERSION."""


class IsoformError(Exception):
    """A C API call failed; str(error) is isoform_last_error()."""

    def __init__(self, message, status=None, status_name=""):
        super().__init__(message)
        self.status = status
        self.status_name = status_name


class CancelledError(IsoformError):
    """The call stopped because its Progress was cancelled."""


def version_text(version):
    return f"{version // 10000}.{version // 100 % 100}.{version % 100}"


class Library:
    """One loaded libisoform with every signature declared."""

    def __init__(self, path=None, expected_version=ISOFORM_VERSION):
        self.path = path or find_library()
        try:
            self.dll = ctypes.CDLL(self.path)
        except OSError as error:
            raise LibraryError(f"{self.path}: cannot load the isoform library ({error})") from None
        self.version = self._check_version(expected_version)
        for name, (restype, argtypes) in _SIGNATURES.items():
            function = self._symbol(name)
            function.restype, function.argtypes = restype, argtypes
            setattr(self, name[len("isoform_"):], function)

    def _symbol(self, name):
        try:
            return getattr(self.dll, name)
        except AttributeError:
            raise LibraryError(f"{self.path}: no symbol {name}; not the isoform library "
                               f"this add-on was built with") from None

    # NOTE: checked before any other symbol is declared or called: a library
    # of another version may have other struct layouts.
    def _check_version(self, expected):
        function = self._symbol("isoform_version")
        function.restype, function.argtypes = ctypes.c_int, []
        found = function()
        if found != expected:
            raise VersionMismatch(f"{self.path} is isoform {version_text(found)}, but this add-on "
                                  f"needs isoform {version_text(expected)}; install the matching "
                                  f"add-on zip")
        return found

    def check(self, status):
        """Raises IsoformError with the library's message unless status is OK."""
        if status == 0:
            return
        message = self.last_error().decode("utf-8", "replace")
        name = self.status_name(status).decode("ascii", "replace")
        kind = CancelledError if status == STATUS_CANCELLED else IsoformError
        raise kind(message or name, status, name)


def find_library():
    """Beside this module first (the installed zip), then $ISOFORM_LIBRARY."""
    beside = os.path.join(os.path.dirname(os.path.abspath(__file__)), LIBRARY_FILE)
    if os.path.isfile(beside):
        return beside
    from_env = os.environ.get(LIBRARY_ENV, "")
    if from_env:
        if not os.path.isfile(from_env):
            raise LibraryError(f"{LIBRARY_ENV}={from_env}: no such file")
        return from_env
    raise LibraryError(f"{LIBRARY_FILE} is not beside {beside} and {LIBRARY_ENV} is not set")


_library = None
_library_lock = threading.Lock()


def library():
    """The process-wide Library, loaded on first use."""
    global _library
    with _library_lock:
        if _library is None:
            _library = Library()
        return _library


def _path_bytes(path):
    return os.fsencode(os.fspath(path))


def _as_c(array, dtype, columns):
    """A C-contiguous (rows, columns) copy or view of array with this dtype."""
    out = np.ascontiguousarray(array, dtype=dtype)
    if out.ndim == 1 and out.size % columns == 0:
        out = out.reshape(-1, columns)
    if out.ndim != 2 or out.shape[1] != columns:
        raise ValueError(f"expected an array of shape (n, {columns}), got {np.shape(array)}")
    return out


def _struct_namespace(value):
    """A ctypes struct as a SimpleNamespace of Python values."""
    fields = {}
    for name, _ in value._fields_:
        item = getattr(value, name)
        if isinstance(item, bytes):
            item = item.decode("utf-8", "replace")
        elif isinstance(item, ctypes.Array):
            item = tuple(item)
        fields[name] = item
    return SimpleNamespace(**fields)


# ---------------------------------------------------------------- progress

class Progress:
    """An isoform_progress that one thread passes to a call and another polls."""

    def __init__(self):
        self.struct = structs.Progress()

    @property
    def fraction(self):
        return float(self.struct.fraction)

    @property
    def stage(self):
        return int(self.struct.stage)

    @property
    def stage_name(self):
        return STAGE_NAMES.get(self.stage, "working")

    def cancel(self):
        self.struct.cancel = 1

    @property
    def cancelled(self):
        return self.struct.cancel != 0

    def pointer(self):
        return ctypes.byref(self.struct)


def _progress_pointer(progress):
    return progress.pointer() if progress is not None else None


# ---------------------------------------------------------------- handles

class _Handle:
    """Owns one library handle; freed by close(), with, or garbage collection."""
    _free_name = ""

    def __init__(self, lib, handle):
        self._lib = lib
        self._handle = handle

    @property
    def handle(self):
        if not self._handle:
            raise ValueError(f"{type(self).__name__} is closed")
        return self._handle

    def close(self):
        if self._handle:
            getattr(self._lib, self._free_name)(self._handle)
            self._handle = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        self.close()


def _make(cls, create):
    """Calls create(lib, out_pointer), checks it, wraps the handle in cls."""
    lib = library()
    out = ctypes.c_void_p()
    lib.check(create(lib, ctypes.byref(out)))
    return cls(lib, out.value)


class Volume(_Handle):
    """An isoform_volume: the grids of a file, a dense array or the phantom."""
    _free_name = "volume_free"

    @classmethod
    def open(cls, path, volume=None):
        """Opens a .vdb, .nrrd/.nhdr or .nii/.nii.gz file; volume picks one
        volume (from 0) of a 4-D NIfTI, which is refused without it."""
        lib = library()
        options = structs.OpenOptions()
        lib.open_options_default(ctypes.byref(options))
        if volume is not None:
            options.volume = int(volume)
        return _make(cls, lambda lib, out: lib.volume_open_with(
            _path_bytes(path), ctypes.byref(options), out))

    @classmethod
    def phantom(cls, n=128):
        return _make(cls, lambda lib, out: lib.volume_phantom(int(n), out))

    @classmethod
    def from_dense(cls, values, spacing=None, origin=None, name=None, grid_class=CLASS_FOG):
        """values: an array of shape (nz, ny, nx), so that x varies fastest."""
        dense = np.ascontiguousarray(values, dtype=np.float32)
        if dense.ndim != 3:
            raise ValueError(f"expected a 3-D array (nz, ny, nx), got shape {dense.shape}")
        nz, ny, nx = dense.shape
        triple = lambda v: None if v is None else (ctypes.c_double * 3)(*v)  # noqa: E731
        return _make(cls, lambda lib, out: lib.volume_from_dense(
            dense.ctypes.data_as(_f32), nx, ny, nz, triple(spacing), triple(origin),
            None if name is None else name.encode("utf-8"), int(grid_class), out))

    @property
    def grid_count(self):
        return self._lib.volume_grid_count(self.handle)

    def grid_info(self, index):
        info = structs.GridInfo()
        self._lib.check(self._lib.volume_grid_info(self.handle, int(index), ctypes.byref(info)))
        return _struct_namespace(info)

    def grids(self):
        return [self.grid_info(i) for i in range(self.grid_count)]

    def find_grid(self, name=""):
        """Index of the grid called name ("" = the first scalar grid)."""
        index = self._lib.volume_find_grid(self.handle, (name or "").encode("utf-8"))
        if index < 0:
            raise IsoformError(self._lib.last_error().decode("utf-8", "replace"))
        return index

    def save_vdb(self, path):
        self._lib.check(self._lib.volume_save_vdb(self.handle, _path_bytes(path)))

    def contour(self, grid="", isovalue=None, method="cells", orientation="auto", threads=0,
                progress=None):
        """The contour of a grid (a name or an index) as a Mesh.

        isovalue None lets the library choose (level set 0, else the middle of
        the value range); method "cells" or "tetra"."""
        index = grid if isinstance(grid, int) else self.find_grid(grid)
        options = structs.ContourOptions()
        self._lib.contour_options_default(ctypes.byref(options))
        options.auto_isovalue = 1 if isovalue is None else 0
        options.isovalue = 0.0 if isovalue is None else float(isovalue)
        options.method = _choice(METHODS, method, "method")
        options.orientation = _choice(ORIENTATIONS, orientation, "orientation")
        options.threads = int(threads)
        return _make(Mesh, lambda lib, out: lib.contour(
            self.handle, index, ctypes.byref(options), _progress_pointer(progress), out))


def _choice(table, key, what):
    if key not in table:
        raise ValueError(f"unknown {what} {key!r}; expected one of {', '.join(table)}")
    return table[key]


class Mesh(_Handle):
    """An isoform_mesh: points, normals, triangles, neighbours, parts."""
    _free_name = "mesh_free"

    @classmethod
    def from_arrays(cls, points, triangles):
        """A mesh from (n, 3) points and (m, 3) vertex indices (copied).

        Neighbours, parts and statistics are computed; normals are estimated
        from the mesh. Later operators hand Blender meshes to the library
        through this."""
        p = _as_c(points, np.float32, 3)
        t = _as_c(triangles, np.int32, 3)
        return _make(cls, lambda lib, out: lib.mesh_from_arrays(
            p.ctypes.data_as(_f32), p.shape[0], t.ctypes.data_as(_i32), t.shape[0], out))

    @classmethod
    def from_arrays_f64(cls, points, triangles):
        """As from_arrays with double-precision points, which the library keeps
        for curvature fits (float32 alone limits their accuracy on fine meshes)."""
        p = _as_c(points, np.float64, 3)
        t = _as_c(triangles, np.int32, 3)
        return _make(cls, lambda lib, out: lib.mesh_from_arrays_f64(
            p.ctypes.data_as(_f64), p.shape[0], t.ctypes.data_as(_i32), t.shape[0], out))

    @classmethod
    def load(cls, path):
        return _make(cls, lambda lib, out: lib.mesh_load(_path_bytes(path), out))

    def transform(self, matrix):
        """Moves the mesh by a row-major 4x4 affine matrix (last row 0 0 0 1);
        a mirror reverses the winding so that it agrees with the normals."""
        values = np.ascontiguousarray(matrix, dtype=np.float64).reshape(16)
        self._lib.check(self._lib.mesh_transform(self.handle, values.ctypes.data_as(_f64)))

    def filter_parts(self, min_triangles=0, min_volume=0.0, largest=0):
        """Drops the parts of fewer triangles, the closed parts enclosing less
        than min_volume (world units cubed), or all but the largest; returns
        what was dropped (parts_before, parts_after, triangles_before,
        triangles_after)."""
        options = structs.PartFilter()
        self._lib.part_filter_default(ctypes.byref(options))
        options.min_triangles = int(min_triangles)
        options.min_volume = float(min_volume)
        options.largest = int(largest)
        stats = structs.PartFilterStats()
        self._lib.check(self._lib.mesh_filter_parts(self.handle, ctypes.byref(options),
                                                    ctypes.byref(stats)))
        return _struct_namespace(stats)

    def save(self, path):
        self._lib.check(self._lib.mesh_save(self.handle, _path_bytes(path)))

    @property
    def vertex_count(self):
        return self._lib.mesh_vertex_count(self.handle)

    @property
    def triangle_count(self):
        return self._lib.mesh_triangle_count(self.handle)

    @property
    def part_count(self):
        return self._lib.mesh_part_count(self.handle)

    def stats(self):
        out = structs.MeshStats()
        self._lib.check(self._lib.mesh_stats_get(self.handle, ctypes.byref(out)))
        return _struct_namespace(out)

    def _copy(self, function, rows, shape, dtype, pointer):
        out = np.empty((rows,) + shape, dtype=dtype)
        self._lib.check(function(self.handle, out.ctypes.data_as(pointer)))
        return out

    def points(self):
        return self._copy(self._lib.mesh_copy_points, self.vertex_count, (3,), np.float32, _f32)

    def normals(self):
        return self._copy(self._lib.mesh_copy_normals, self.vertex_count, (3,), np.float32, _f32)

    def set_normals(self, normals):
        """Replaces the normals by (n, 3) values, each scaled to unit length."""
        n = _as_c(normals, np.float32, 3)
        if n.shape[0] != self.vertex_count:
            raise ValueError(f"{n.shape[0]} normals for {self.vertex_count} vertices")
        self._lib.check(self._lib.mesh_set_normals(self.handle, n.ctypes.data_as(_f32)))

    def triangles(self):
        return self._copy(self._lib.mesh_copy_triangles, self.triangle_count, (3,), np.int32, _i32)

    def neighbours(self):
        return self._copy(self._lib.mesh_copy_neighbours, self.triangle_count, (3,), np.int32,
                          _i32)

    def parts(self):
        return self._copy(self._lib.mesh_copy_parts, self.triangle_count, (), np.int32, _i32)

    def curvature(self, method="quartic", extra_rings=0, color_by="mean", threads=0,
                  progress=None):
        """Runs isoform_curvature on this mesh (Section 4.2); returns its stats.
        Sign: positive where the surface bends away from its normal."""
        options = structs.CurvatureOptions()
        self._lib.curvature_options_default(ctypes.byref(options))
        options.method = _choice(CURVATURE_METHODS, method, "curvature method")
        options.extra_rings = int(extra_rings)
        options.color_by = _choice(CURVATURE_QUANTITIES, color_by, "colour quantity")
        options.threads = int(threads)
        self._lib.check(self._lib.curvature(self.handle, ctypes.byref(options),
                                            _progress_pointer(progress)))
        return self.curvature_stats()

    @property
    def has_curvature(self):
        return bool(self._lib.mesh_has_curvature(self.handle))

    def curvature_stats(self):
        out = structs.CurvatureStats()
        self._lib.check(self._lib.mesh_curvature_stats(self.handle, ctypes.byref(out)))
        return _struct_namespace(out)

    def curvature_values(self, quantity):
        """One quantity per vertex: (n,) float32, or (n, 3) for "d1", "d2"."""
        if quantity in CURVATURE_DIRECTIONS:
            code, shape = CURVATURE_DIRECTIONS[quantity], (3,)
        else:
            code, shape = _choice(CURVATURE_QUANTITIES, quantity, "curvature quantity"), ()
        out = np.empty((self.vertex_count,) + shape, dtype=np.float32)
        self._lib.check(self._lib.mesh_copy_curvature(self.handle, code, out.ctypes.data_as(_f32)))
        return out

    def curvature_flags(self):
        return self._copy(self._lib.mesh_copy_curvature_flags, self.vertex_count, (), np.uint8,
                          _u8)

    def colors(self):
        """(n, 4) uint8 RGBA per vertex, or None when the mesh has no colours."""
        if self._lib.mesh_color_count(self.handle) == 0:
            return None
        return self._copy(self._lib.mesh_copy_colors, self.vertex_count, (4,), np.uint8, _u8)

    def edges(self):
        """(e, 2) int32 vertex indices of the loose edges (curves, box outlines)."""
        count = self._lib.mesh_edge_count(self.handle)
        return self._copy(self._lib.mesh_copy_edges, count, (2,), np.int32, _i32)

    def arrays(self):
        """Everything a Blender mesh is built from, as numpy arrays."""
        return MeshArrays(self.points(), self.normals(), self.triangles(), self.parts(),
                          self.stats())


class MeshArrays(SimpleNamespace):
    """points (n, 3) float32, normals (n, 3) float32, triangles (m, 3) int32,
    parts (m,) int32 and the library's stats; no handle, safe to pass between
    threads."""

    def __init__(self, points, normals, triangles, parts, stats):
        super().__init__(points=points, normals=normals, triangles=triangles, parts=parts,
                         stats=stats)


def contour_file(path, grid="", isovalue=None, method="cells", progress=None, volume=None,
                 min_part=0):
    """Opens a volume file and contours one grid: the operators' whole job.
    volume picks the volume of a 4-D NIfTI; parts of fewer than min_part
    triangles are dropped. The arrays also carry the grid's world unit ("mm",
    "m", "um" or "") as unit."""
    with Volume.open(path, volume=volume) as opened:
        index = grid if isinstance(grid, int) else opened.find_grid(grid)
        unit = opened.grid_info(index).unit
        with opened.contour(index, isovalue=isovalue, method=method, progress=progress) as mesh:
            if min_part > 0:
                mesh.filter_parts(min_triangles=min_part)
            arrays = mesh.arrays()
    arrays.unit = unit
    return arrays
