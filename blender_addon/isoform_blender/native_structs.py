"""ctypes mirrors of the plain structs of isoform.h, field by field.

The order, names and C types here must match libcore/isoform.h exactly: a
mismatch is not detected by ctypes and silently corrupts memory. The test
tests/blender/test_native.py compares every size and offset below with the
values a C program compiled against isoform.h reports (struct_layout.c).
Plain ctypes, no bpy, no numpy.
"""
import ctypes

c_long_long = ctypes.c_longlong


class Progress(ctypes.Structure):
    """isoform_progress: written by the library, cancel set by the caller."""
    _fields_ = [
        ("fraction", ctypes.c_float),  # 0..1 within the current stage
        ("stage", ctypes.c_int),       # an isoform_stage value
        ("cancel", ctypes.c_int),      # non-zero asks the running call to stop
    ]


class GridInfo(ctypes.Structure):
    """isoform_grid_info: facts about one grid."""
    _fields_ = [
        ("name", ctypes.c_char * 256),
        ("value_type", ctypes.c_char * 32),
        ("grid_class", ctypes.c_int),
        ("is_scalar", ctypes.c_int),
        ("value_min", ctypes.c_double),
        ("value_max", ctypes.c_double),
        ("background", ctypes.c_double),
        ("active_voxels", c_long_long),
        ("bbox_min", ctypes.c_int * 3),
        ("bbox_max", ctypes.c_int * 3),
        ("voxel_size", ctypes.c_double * 3),
        ("transform", ctypes.c_double * 16),  # row-major index -> world
        ("space", ctypes.c_char * 8),         # "RAS", "LPS", "LAS" or "" (not stated)
        ("unit", ctypes.c_char * 8),          # "mm", "m", "um" or ""
    ]


class OpenOptions(ctypes.Structure):
    """isoform_open_options: choices for opening a volume file."""
    _fields_ = [
        ("struct_size", ctypes.c_size_t),
        ("volume", ctypes.c_int),  # volume of a 4-D NIfTI; -1 refuses 4-D files
    ]


class RawOptions(ctypes.Structure):
    """isoform_raw_options: how to read a headerless raw scan."""
    _fields_ = [
        ("dims", ctypes.c_int * 3),
        ("scalar_type", ctypes.c_int),
        ("big_endian", ctypes.c_int),
        ("spacing", ctypes.c_double * 3),
        ("origin", ctypes.c_double * 3),
        ("header_bytes", ctypes.c_size_t),
    ]


class PartFilter(ctypes.Structure):
    """isoform_part_filter: which parts of a mesh to keep."""
    _fields_ = [
        ("struct_size", ctypes.c_size_t),
        ("min_triangles", c_long_long),  # drop parts of fewer triangles; 0 keeps all
        ("min_volume", ctypes.c_double),  # drop closed parts enclosing less; 0 keeps all
        ("largest", c_long_long),        # keep the K largest parts; 0 keeps all
    ]


class PartFilterStats(ctypes.Structure):
    """isoform_part_filter_stats: what isoform_mesh_filter_parts dropped."""
    _fields_ = [
        ("parts_before", c_long_long),
        ("parts_after", c_long_long),
        ("triangles_before", c_long_long),
        ("triangles_after", c_long_long),
    ]


class ContourOptions(ctypes.Structure):
    """isoform_contour_options."""
    _fields_ = [
        ("isovalue", ctypes.c_double),
        ("auto_isovalue", ctypes.c_int),
        ("method", ctypes.c_int),
        ("orientation", ctypes.c_int),
        ("threads", ctypes.c_int),
    ]


class MeshStats(ctypes.Structure):
    """isoform_mesh_stats: facts computed when a mesh was made."""
    _fields_ = [
        ("vertices", c_long_long),
        ("triangles", c_long_long),
        ("parts", c_long_long),
        ("boundary_edges", c_long_long),
        ("nonmanifold_edges", c_long_long),
        ("inconsistent_edges", c_long_long),
        ("degenerate_triangles", c_long_long),
        ("euler_characteristic", c_long_long),
        ("isovalue", ctypes.c_double),
        ("isovalue_was_auto", ctypes.c_int),
        ("ambiguous_faces", c_long_long),
        ("degenerate_saddles", c_long_long),
        ("extra_points", c_long_long),
        ("centroid_points", c_long_long),
        ("near_sample_points", c_long_long),
        ("bbox_min", ctypes.c_double * 3),
        ("bbox_max", ctypes.c_double * 3),
    ]


class CurvatureOptions(ctypes.Structure):
    """isoform_curvature_options."""
    _fields_ = [
        ("method", ctypes.c_int),
        ("extra_rings", ctypes.c_int),
        ("color_by", ctypes.c_int),
        ("update_normals", ctypes.c_int),
        ("threads", ctypes.c_int),
    ]


class CurvatureStats(ctypes.Structure):
    """isoform_curvature_stats: vertex counts per fallback, colour range."""
    _fields_ = [
        ("method", ctypes.c_int),
        ("color_by", ctypes.c_int),
        ("vertices", c_long_long),
        ("boundary", c_long_long),
        ("widened", c_long_long),
        ("lower_order", c_long_long),
        ("nonmanifold", c_long_long),
        ("isolated", c_long_long),
        ("failed", c_long_long),
        ("normal_repaired", c_long_long),
        ("color_min", ctypes.c_double),
        ("color_max", ctypes.c_double),
    ]


class ColourOptions(ctypes.Structure):
    """isoform_colour_options: the linear colour-index map of Section 2.2."""
    _fields_ = [
        ("map", ctypes.c_int),
        ("levels", ctypes.c_int),
        ("fixed_range", ctypes.c_int),
        ("range_min", ctypes.c_double),
        ("range_max", ctypes.c_double),
    ]


class SliceOptions(ctypes.Structure):
    """isoform_slice_options."""
    _fields_ = [
        ("position", ctypes.c_double * 3),
        ("world", ctypes.c_int),
        ("resolution", ctypes.c_int),
        ("colour_bar", ctypes.c_int),
        ("height", ctypes.c_double),
        ("colour", ColourOptions),
    ]


class BoxesOptions(ctypes.Structure):
    """isoform_boxes_options."""
    _fields_ = [
        ("q", ctypes.c_int * 3),
        ("gap", ctypes.c_double * 3),
        ("face_cells", ctypes.c_int * 2),
        ("centroid_lines", ctypes.c_int),
        ("domain", ctypes.c_int),
        ("uvw_min", ctypes.c_double * 3),
        ("uvw_max", ctypes.c_double * 3),
        ("centre", ctypes.c_double * 3),
        ("colour", ColourOptions),
    ]


class StackOptions(ctypes.Structure):
    """isoform_stack_options."""
    _fields_ = [
        ("n", ctypes.c_int * 3),
        ("transparency", ctypes.c_double),
        ("view", ctypes.c_double * 3),
        ("colour", ColourOptions),
    ]


class ReduceOptions(ctypes.Structure):
    """isoform_reduce_options (Chapter 5)."""
    _fields_ = [
        ("keep_fraction", ctypes.c_double),
        ("tolerance", ctypes.c_double),
        ("lock_boundary", ctypes.c_int),
        ("point_method", ctypes.c_int),
        ("graph", ctypes.c_int),
        ("graph_rms_tolerance", ctypes.c_double),
        ("swaps", ctypes.c_int),
        ("measure_error", ctypes.c_int),
        ("refine_point", ctypes.c_int),
        ("vertex_fallback", ctypes.c_int),
        ("manifold_parts_only", ctypes.c_int),
        ("prevent_overlap", ctypes.c_int),
    ]


class ReduceStats(ctypes.Structure):
    """isoform_reduce_stats: what the last reduction of a mesh did."""
    _fields_ = [
        ("triangles_before", c_long_long),
        ("triangles_after", c_long_long),
        ("vertices_before", c_long_long),
        ("vertices_after", c_long_long),
        ("removals", c_long_long),
        ("swaps", c_long_long),
        ("vertex_points", c_long_long),
        ("passes", ctypes.c_int),
        ("curvature_computed", ctypes.c_int),
        ("stop_reason", ctypes.c_int),
        ("max_distance", ctypes.c_double),
        ("graph_rms", ctypes.c_double),
        ("refused_corona", c_long_long),
        ("refused_half_plane", c_long_long),
        ("refused_flip", c_long_long),
        ("refused_nonmanifold", c_long_long),
        ("refused_boundary", c_long_long),
        ("refused_tolerance", c_long_long),
        ("parts_left_alone", c_long_long),
        ("triangles_left_alone", c_long_long),
        ("refused_overlap", c_long_long),
        ("kernel_points", c_long_long),
    ]


class PatchOptions(ctypes.Structure):
    """isoform_patch_options (Chapter 6)."""
    _fields_ = [
        ("blend", ctypes.c_int),
        ("tension", ctypes.c_double),
        ("edge_tension_count", ctypes.c_size_t),
        ("edge_tension_vertices", ctypes.POINTER(ctypes.c_int32)),
        ("edge_tension_values", ctypes.POINTER(ctypes.c_double)),
    ]


class PatchStats(ctypes.Structure):
    """isoform_patch_stats: what building the side-vertex surface met."""
    _fields_ = [
        ("triangles", c_long_long),
        ("edges", c_long_long),
        ("nonconvex_edges", c_long_long),
        ("opposite_normal_edges", c_long_long),
        ("fallback_plane_edges", c_long_long),
    ]


class CompareOptions(ctypes.Structure):
    """isoform_compare_options (the comparison with the Loop limit surface)."""
    _fields_ = [
        ("level", ctypes.c_int),
        ("reference", ctypes.c_int),
        ("fit_reference", ctypes.c_int),
        ("centre", ctypes.c_double * 3),
        ("radius", ctypes.c_double),
        ("minor_radius", ctypes.c_double),
        ("grid", ctypes.c_int),
        ("isovalue", ctypes.c_double),
        ("loop_isolation", ctypes.c_int),
        ("loop_sharp_corners", ctypes.c_int),
        ("table_triangles", c_long_long),
        ("input_name", ctypes.c_char_p),
        ("side_vertex", ctypes.c_int),
    ]


class CompareStats(ctypes.Structure):
    """isoform_compare_stats: |x| over samples."""
    _fields_ = [
        ("count", c_long_long),
        ("max", ctypes.c_double),
        ("rms", ctypes.c_double),
        ("mean", ctypes.c_double),
    ]


class CompareSpread(ctypes.Structure):
    """isoform_compare_spread: a signed quantity's distribution."""
    _fields_ = [
        ("count", c_long_long),
        ("p05", ctypes.c_double),
        ("p50", ctypes.c_double),
        ("p95", ctypes.c_double),
        ("mean", ctypes.c_double),
        ("stddev", ctypes.c_double),
    ]


class CompareMetrics(ctypes.Structure):
    """isoform_compare_metrics: the measures of one surface."""
    _fields_ = [
        ("samples", c_long_long),
        ("failed_samples", c_long_long),
        ("deviation", CompareStats),
        ("data_point_error", CompareStats),
        ("normal_gap", CompareStats),
        ("position_gap", CompareStats),
        ("mean_curvature_jump", CompareStats),
        ("mean_curvature_error", CompareStats),
        ("mean_curvature", CompareSpread),
        ("gauss_curvature", CompareSpread),
        ("evaluation_seconds", ctypes.c_double),
        ("seconds_per_million", ctypes.c_double),
        ("tessellation_triangles", c_long_long),
    ]


# Every mirrored struct by its C name; the layout test walks this table.
STRUCTS = {
    "isoform_progress": Progress,
    "isoform_grid_info": GridInfo,
    "isoform_open_options": OpenOptions,
    "isoform_raw_options": RawOptions,
    "isoform_contour_options": ContourOptions,
    "isoform_mesh_stats": MeshStats,
    "isoform_part_filter": PartFilter,
    "isoform_part_filter_stats": PartFilterStats,
    "isoform_curvature_options": CurvatureOptions,
    "isoform_curvature_stats": CurvatureStats,
    "isoform_colour_options": ColourOptions,
    "isoform_slice_options": SliceOptions,
    "isoform_boxes_options": BoxesOptions,
    "isoform_stack_options": StackOptions,
    "isoform_reduce_options": ReduceOptions,
    "isoform_reduce_stats": ReduceStats,
    "isoform_patch_options": PatchOptions,
    "isoform_patch_stats": PatchStats,
    "isoform_compare_options": CompareOptions,
    "isoform_compare_stats": CompareStats,
    "isoform_compare_spread": CompareSpread,
    "isoform_compare_metrics": CompareMetrics,
}
