"""The volume visualisation of Chapter 2 (isoform.h "Volume visualisation")
through ctypes, without bpy: slices, domain-subdivision boxes, transparency
stacks as native.Mesh handles with colours, and slice images.

Options are keyword arguments; what is not given keeps the library's default
(isoform_*_options_default). Axis 0, 1, 2 is the plane x = c1, y = c2, z = c3.
"""
import ctypes

import numpy as np

from . import native
from . import native_structs as structs
from .native_signatures import _f32, _u8

COLOUR_MAPS = {"viridis": 0, "diverging": 1, "green-white": 2}
SLICE_KINDS = {"plane": 0, "surface": 1, "curves": 2}
AXES = {"x": 0, "y": 1, "z": 2, "all": 3}


def _colour(options, colour_map=None, levels=None, value_range=None):
    """Fills an isoform_colour_options in place from keyword values."""
    if colour_map is not None:
        options.map = native._choice(COLOUR_MAPS, colour_map, "colour map")
    if levels is not None:
        options.levels = int(levels)
    if value_range is not None:
        options.fixed_range = 1
        options.range_min, options.range_max = (float(v) for v in value_range)


def _triple(values, kind, what):
    items = tuple(values)
    if len(items) != 3:
        raise ValueError(f"{what}: expected 3 values, got {len(items)}")
    return (kind * 3)(*items)


def _grid(volume, grid):
    return grid if isinstance(grid, int) else volume.find_grid(grid)


def slice_options(position=None, world=False, resolution=None, colour_bar=None, height=None,
                  **colour):
    lib = native.library()
    options = structs.SliceOptions()
    lib.slice_options_default(ctypes.byref(options))
    if position is not None:
        options.position = _triple(position, ctypes.c_double, "position")
    options.world = 1 if world else 0
    if resolution is not None:
        options.resolution = int(resolution)
    if colour_bar is not None:
        options.colour_bar = 1 if colour_bar else 0
    if height is not None:
        options.height = float(height)
    _colour(options.colour, **colour)
    return options


def slice_mesh(volume, grid="", axis=3, kind="plane", **keywords):
    """The slices of axis 0, 1, 2 (or all three: 3) as a coloured Mesh in the
    grid's world coordinates; keywords as slice_options."""
    options = slice_options(**keywords)
    index = _grid(volume, grid)
    return native._make(native.Mesh, lambda lib, out: lib.slice_mesh(
        volume.handle, index, int(axis), native._choice(SLICE_KINDS, kind, "slice kind"),
        ctypes.byref(options), out))


def slice_image(volume, grid="", axis=0, **keywords):
    """Slice `axis` sampled into an Image (with a colour bar unless colour_bar=False)."""
    options = slice_options(**keywords)
    index = _grid(volume, grid)
    return native._make(Image, lambda lib, out: lib.slice_image(
        volume.handle, index, int(axis), ctypes.byref(options), out))


def boxes(volume, grid="", q=(5, 5, 5), gap=None, face_cells=None, centroid_lines=False,
          **colour):
    """The domain-subdivision boxes of Section 2.2 over the grid's box domain;
    gap is alpha (one value for all axes or three)."""
    lib = native.library()
    options = structs.BoxesOptions()
    lib.boxes_options_default(ctypes.byref(options))
    options.q = _triple(q, ctypes.c_int, "q")
    if gap is not None:
        gaps = (gap,) * 3 if np.isscalar(gap) else gap
        options.gap = _triple(gaps, ctypes.c_double, "gap")
    if face_cells is not None:
        options.face_cells = (ctypes.c_int * 2)(*face_cells)
    options.centroid_lines = 1 if centroid_lines else 0
    _colour(options.colour, **colour)
    index = _grid(volume, grid)
    return native._make(native.Mesh, lambda lib, out: lib.boxes(
        volume.handle, index, ctypes.byref(options), out))


def stack(volume, grid="", n=(8, 8, 8), transparency=None, view=None, **colour):
    """The transparency stack of Section 2.2, sorted back to front along view
    (world direction from the eye into the scene)."""
    lib = native.library()
    options = structs.StackOptions()
    lib.stack_options_default(ctypes.byref(options))
    options.n = _triple(n, ctypes.c_int, "n")
    if transparency is not None:
        options.transparency = float(transparency)
    if view is not None:
        options.view = _triple(view, ctypes.c_double, "view")
    _colour(options.colour, **colour)
    index = _grid(volume, grid)
    return native._make(native.Mesh, lambda lib, out: lib.stack(
        volume.handle, index, ctypes.byref(options), out))


class Image(native._Handle):
    """An isoform_image: RGBA rows top to bottom, and the value of each pixel."""
    _free_name = "image_free"

    @property
    def width(self):
        return self._lib.image_width(self.handle)

    @property
    def height(self):
        return self._lib.image_height(self.handle)

    def value_range(self):
        low, high = ctypes.c_double(), ctypes.c_double()
        self._lib.check(self._lib.image_range(self.handle, ctypes.byref(low), ctypes.byref(high)))
        return low.value, high.value

    def rgba(self):
        out = np.empty((self.height, self.width, 4), dtype=np.uint8)
        self._lib.check(self._lib.image_copy_rgba(self.handle, out.ctypes.data_as(_u8)))
        return out

    def values(self):
        """(height, width) float32; NaN on the colour bar and its margin."""
        out = np.empty((self.height, self.width), dtype=np.float32)
        self._lib.check(self._lib.image_copy_values(self.handle, out.ctypes.data_as(_f32)))
        return out

    def save_png(self, path):
        self._lib.check(self._lib.image_save_png(self.handle, native._path_bytes(path)))


class ColouredArrays:
    """What a Blender mesh is built from for the visualisation objects: points
    (n, 3) float32, triangles (m, 3) int32, edges (e, 2) int32, colours
    (n, 4) uint8 or None; no handle, safe to pass between threads."""

    def __init__(self, mesh):
        self.points = mesh.points()
        self.triangles = mesh.triangles()
        self.edges = mesh.edges()
        self.colors = mesh.colors()


def coloured_arrays(mesh):
    """Copies a visualisation Mesh out and frees it."""
    with mesh:
        return ColouredArrays(mesh)
