"""The C signatures of libcore/isoform.h that native.py declares: for each
function its ctypes restype and argtypes, the C parameter names in a comment.
Plain ctypes, no bpy, no numpy."""
import ctypes

from . import native_structs as structs

_ptr = ctypes.POINTER
_u8 = ctypes.POINTER(ctypes.c_uint8)
_handle = ctypes.c_void_p
_handle_out = ctypes.POINTER(ctypes.c_void_p)
_f32 = ctypes.POINTER(ctypes.c_float)
_i32 = ctypes.POINTER(ctypes.c_int32)
_f64 = ctypes.POINTER(ctypes.c_double)
_int, _size, _str = ctypes.c_int, ctypes.c_size_t, ctypes.c_char_p

# name: (restype, argtypes). isoform_version is declared on its own, first.
SIGNATURES = {
    "isoform_last_error": (_str, []),
    "isoform_status_name": (_str, [_int]),  # status
    "isoform_volume_open": (_int, [_str, _handle_out]),  # path, out
    "isoform_open_options_default": (None, [ctypes.POINTER(structs.OpenOptions)]),
    # path, options, out
    "isoform_volume_open_with": (_int, [_str, ctypes.POINTER(structs.OpenOptions), _handle_out]),
    # values, nx, ny, nz, spacing[3], origin[3], name, grid_class, out
    "isoform_volume_from_dense": (_int, [_f32, _int, _int, _int, _f64, _f64, _str, _int,
                                         _handle_out]),
    "isoform_volume_phantom": (_int, [_int, _handle_out]),  # n, out
    "isoform_volume_save_vdb": (_int, [_handle, _str]),  # volume, path
    "isoform_volume_free": (None, [_handle]),  # volume
    "isoform_volume_grid_count": (_int, [_handle]),  # volume
    # volume, index, out
    "isoform_volume_grid_info": (_int, [_handle, _int, ctypes.POINTER(structs.GridInfo)]),
    "isoform_volume_find_grid": (_int, [_handle, _str]),  # volume, name
    "isoform_contour_options_default": (None, [ctypes.POINTER(structs.ContourOptions)]),
    # volume, grid, options, progress, out
    "isoform_contour": (_int, [_handle, _int, ctypes.POINTER(structs.ContourOptions),
                               ctypes.POINTER(structs.Progress), _handle_out]),
    "isoform_mesh_stats_get": (_int, [_handle, ctypes.POINTER(structs.MeshStats)]),  # mesh, out
    "isoform_mesh_transform": (_int, [_handle, _f64]),  # mesh, matrix[16]
    "isoform_part_filter_default": (None, [ctypes.POINTER(structs.PartFilter)]),
    # mesh, filter, stats
    "isoform_mesh_filter_parts": (_int, [_handle, ctypes.POINTER(structs.PartFilter),
                                         ctypes.POINTER(structs.PartFilterStats)]),
    "isoform_mesh_vertex_count": (_size, [_handle]),  # mesh
    "isoform_mesh_triangle_count": (_size, [_handle]),  # mesh
    "isoform_mesh_part_count": (_size, [_handle]),  # mesh
    "isoform_mesh_copy_points": (_int, [_handle, _f32]),  # mesh, out
    "isoform_mesh_copy_normals": (_int, [_handle, _f32]),  # mesh, out
    "isoform_mesh_copy_triangles": (_int, [_handle, _i32]),  # mesh, out
    "isoform_mesh_copy_neighbours": (_int, [_handle, _i32]),  # mesh, out
    "isoform_mesh_copy_parts": (_int, [_handle, _i32]),  # mesh, out
    # points, n, triangles, m, out
    "isoform_mesh_from_arrays": (_int, [_f32, _size, _i32, _size, _handle_out]),
    "isoform_mesh_load": (_int, [_str, _handle_out]),  # path, out
    "isoform_mesh_save": (_int, [_handle, _str]),  # mesh, path
    "isoform_mesh_free": (None, [_handle]),  # mesh
    # Curvature of surfaces
    "isoform_curvature_options_default": (None, [_ptr(structs.CurvatureOptions)]),  # options
    # mesh, options, progress
    "isoform_curvature": (_int, [_handle, _ptr(structs.CurvatureOptions), _ptr(structs.Progress)]),
    "isoform_mesh_has_curvature": (_int, [_handle]),  # mesh
    # mesh, out
    "isoform_mesh_curvature_stats": (_int, [_handle, _ptr(structs.CurvatureStats)]),
    "isoform_mesh_copy_curvature": (_int, [_handle, _int, _f32]),  # mesh, quantity, out
    "isoform_mesh_copy_curvature_flags": (_int, [_handle, _u8]),  # mesh, out
    # points (double), n, triangles, m, out
    "isoform_mesh_from_arrays_f64": (_int, [_f64, _size, _i32, _size, _handle_out]),
    # Volume visualisation
    "isoform_colour_options_default": (None, [_ptr(structs.ColourOptions)]),  # options
    "isoform_slice_options_default": (None, [_ptr(structs.SliceOptions)]),  # options
    # volume, grid, axis, options, out
    "isoform_slice_image": (_int, [_handle, _int, _int, _ptr(structs.SliceOptions), _handle_out]),
    # volume, grid, axis, kind, options, out
    "isoform_slice_mesh": (_int, [_handle, _int, _int, _int, _ptr(structs.SliceOptions),
                                  _handle_out]),
    "isoform_boxes_options_default": (None, [_ptr(structs.BoxesOptions)]),  # options
    # volume, grid, options, out
    "isoform_boxes": (_int, [_handle, _int, _ptr(structs.BoxesOptions), _handle_out]),
    "isoform_stack_options_default": (None, [_ptr(structs.StackOptions)]),  # options
    # volume, grid, options, out
    "isoform_stack": (_int, [_handle, _int, _ptr(structs.StackOptions), _handle_out]),
    "isoform_mesh_color_count": (_size, [_handle]),  # mesh
    "isoform_mesh_copy_colors": (_int, [_handle, _u8]),  # mesh, out
    "isoform_mesh_edge_count": (_size, [_handle]),  # mesh
    "isoform_mesh_copy_edges": (_int, [_handle, _i32]),  # mesh, out
    "isoform_image_width": (_int, [_handle]),  # image
    "isoform_image_height": (_int, [_handle]),  # image
    "isoform_image_range": (_int, [_handle, _f64, _f64]),  # image, f_min, f_max
    "isoform_image_copy_rgba": (_int, [_handle, _u8]),  # image, out
    "isoform_image_copy_values": (_int, [_handle, _f32]),  # image, out
    "isoform_image_save_png": (_int, [_handle, _str]),  # image, path
    "isoform_image_free": (None, [_handle]),  # image
    "isoform_mesh_set_normals": (_int, [_handle, _f32]),  # mesh, normals
    # Reduction (Chapter 5)
    "isoform_reduce_options_default": (None, [_ptr(structs.ReduceOptions)]),  # options
    # mesh, options, progress
    "isoform_reduce": (_int, [_handle, _ptr(structs.ReduceOptions), _ptr(structs.Progress)]),
    "isoform_mesh_reduce_stats": (_int, [_handle, _ptr(structs.ReduceStats)]),  # mesh, out
    # Side-vertex surface (Chapter 6)
    "isoform_patch_options_default": (None, [_ptr(structs.PatchOptions)]),  # options
    "isoform_patch_create": (_int, [_handle, _ptr(structs.PatchOptions), _handle_out]),
    "isoform_patch_free": (None, [_handle]),  # patch
    "isoform_patch_stats_get": (_int, [_handle, _ptr(structs.PatchStats)]),  # patch, out
    # patch, count, triangles, uv, points, normals
    "isoform_patch_evaluate": (_int, [_handle, _size, _i32, _f64, _f64, _f64]),
    # patch, level, progress, out
    "isoform_patch_tessellate": (_int, [_handle, _int, _ptr(structs.Progress), _handle_out]),
    # Comparison with the Loop limit surface
    "isoform_compare_options_default": (None, [_ptr(structs.CompareOptions)]),  # options
    # mesh, reference_or_NULL, options, progress, out
    "isoform_compare": (_int, [_handle, _handle, _ptr(structs.CompareOptions),
                               _ptr(structs.Progress), _handle_out]),
    "isoform_compare_report_surface_count": (_int, [_handle]),  # report
    "isoform_compare_report_surface_name": (_str, [_handle, _int]),  # report, index
    # report, index, out
    "isoform_compare_report_metrics": (_int, [_handle, _int, _ptr(structs.CompareMetrics)]),
    "isoform_compare_report_reference": (_str, [_handle]),  # report
    "isoform_compare_report_deviation_unit": (_str, [_handle]),  # report
    # report, index, out
    "isoform_compare_report_tessellation": (_int, [_handle, _int, _handle_out]),
    "isoform_compare_report_write": (_int, [_handle, _str]),  # report, directory
    "isoform_compare_report_free": (None, [_handle]),  # report
}
