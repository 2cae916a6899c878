/* Prints, as JSON, ISOFORM_VERSION and the size and field offsets of every
 * plain struct of isoform.h, as this C compiler lays them out. The ctypes
 * mirrors of the Blender add-on (native_structs.py) are checked against this
 * output by test_native.py: a silent layout mismatch is the classic ctypes bug. */
#include <stddef.h>
#include <stdio.h>

#include "isoform.h"

static int first_struct = 1;
static int first_field = 1;

static void begin(const char* name, size_t size) {
  printf("%s\n  \"%s\": {\"size\": %zu, \"fields\": [", first_struct ? "" : ",", name, size);
  first_struct = 0;
  first_field = 1;
}

static void field(const char* name, size_t offset, size_t size) {
  printf("%s[\"%s\", %zu, %zu]", first_field ? "" : ", ", name, offset, size);
  first_field = 0;
}

static void end(void) { printf("]}"); }

#define FIELD(type, member) field(#member, offsetof(type, member), sizeof(((type*)0)->member))

int main(void) {
  printf("{\"version\": %d, \"structs\": {", ISOFORM_VERSION);

  begin("isoform_progress", sizeof(isoform_progress));
  FIELD(isoform_progress, fraction);
  FIELD(isoform_progress, stage);
  FIELD(isoform_progress, cancel);
  end();

  begin("isoform_grid_info", sizeof(isoform_grid_info));
  FIELD(isoform_grid_info, name);
  FIELD(isoform_grid_info, value_type);
  FIELD(isoform_grid_info, grid_class);
  FIELD(isoform_grid_info, is_scalar);
  FIELD(isoform_grid_info, value_min);
  FIELD(isoform_grid_info, value_max);
  FIELD(isoform_grid_info, background);
  FIELD(isoform_grid_info, active_voxels);
  FIELD(isoform_grid_info, bbox_min);
  FIELD(isoform_grid_info, bbox_max);
  FIELD(isoform_grid_info, voxel_size);
  FIELD(isoform_grid_info, transform);
  FIELD(isoform_grid_info, space);
  FIELD(isoform_grid_info, unit);
  end();

  begin("isoform_open_options", sizeof(isoform_open_options));
  FIELD(isoform_open_options, struct_size);
  FIELD(isoform_open_options, volume);
  end();

  begin("isoform_part_filter", sizeof(isoform_part_filter));
  FIELD(isoform_part_filter, struct_size);
  FIELD(isoform_part_filter, min_triangles);
  FIELD(isoform_part_filter, min_volume);
  FIELD(isoform_part_filter, largest);
  end();

  begin("isoform_part_filter_stats", sizeof(isoform_part_filter_stats));
  FIELD(isoform_part_filter_stats, parts_before);
  FIELD(isoform_part_filter_stats, parts_after);
  FIELD(isoform_part_filter_stats, triangles_before);
  FIELD(isoform_part_filter_stats, triangles_after);
  end();

  begin("isoform_raw_options", sizeof(isoform_raw_options));
  FIELD(isoform_raw_options, dims);
  FIELD(isoform_raw_options, scalar_type);
  FIELD(isoform_raw_options, big_endian);
  FIELD(isoform_raw_options, spacing);
  FIELD(isoform_raw_options, origin);
  FIELD(isoform_raw_options, header_bytes);
  end();

  begin("isoform_contour_options", sizeof(isoform_contour_options));
  FIELD(isoform_contour_options, isovalue);
  FIELD(isoform_contour_options, auto_isovalue);
  FIELD(isoform_contour_options, method);
  FIELD(isoform_contour_options, orientation);
  FIELD(isoform_contour_options, threads);
  end();

  begin("isoform_mesh_stats", sizeof(isoform_mesh_stats));
  FIELD(isoform_mesh_stats, vertices);
  FIELD(isoform_mesh_stats, triangles);
  FIELD(isoform_mesh_stats, parts);
  FIELD(isoform_mesh_stats, boundary_edges);
  FIELD(isoform_mesh_stats, nonmanifold_edges);
  FIELD(isoform_mesh_stats, inconsistent_edges);
  FIELD(isoform_mesh_stats, degenerate_triangles);
  FIELD(isoform_mesh_stats, euler_characteristic);
  FIELD(isoform_mesh_stats, isovalue);
  FIELD(isoform_mesh_stats, isovalue_was_auto);
  FIELD(isoform_mesh_stats, ambiguous_faces);
  FIELD(isoform_mesh_stats, degenerate_saddles);
  FIELD(isoform_mesh_stats, extra_points);
  FIELD(isoform_mesh_stats, centroid_points);
  FIELD(isoform_mesh_stats, near_sample_points);
  FIELD(isoform_mesh_stats, bbox_min);
  FIELD(isoform_mesh_stats, bbox_max);
  end();

  begin("isoform_curvature_options", sizeof(isoform_curvature_options));
  FIELD(isoform_curvature_options, method);
  FIELD(isoform_curvature_options, extra_rings);
  FIELD(isoform_curvature_options, color_by);
  FIELD(isoform_curvature_options, update_normals);
  FIELD(isoform_curvature_options, threads);
  end();

  begin("isoform_curvature_stats", sizeof(isoform_curvature_stats));
  FIELD(isoform_curvature_stats, method);
  FIELD(isoform_curvature_stats, color_by);
  FIELD(isoform_curvature_stats, vertices);
  FIELD(isoform_curvature_stats, boundary);
  FIELD(isoform_curvature_stats, widened);
  FIELD(isoform_curvature_stats, lower_order);
  FIELD(isoform_curvature_stats, nonmanifold);
  FIELD(isoform_curvature_stats, isolated);
  FIELD(isoform_curvature_stats, failed);
  FIELD(isoform_curvature_stats, normal_repaired);
  FIELD(isoform_curvature_stats, color_min);
  FIELD(isoform_curvature_stats, color_max);
  end();

  begin("isoform_colour_options", sizeof(isoform_colour_options));
  FIELD(isoform_colour_options, map);
  FIELD(isoform_colour_options, levels);
  FIELD(isoform_colour_options, fixed_range);
  FIELD(isoform_colour_options, range_min);
  FIELD(isoform_colour_options, range_max);
  end();

  begin("isoform_slice_options", sizeof(isoform_slice_options));
  FIELD(isoform_slice_options, position);
  FIELD(isoform_slice_options, world);
  FIELD(isoform_slice_options, resolution);
  FIELD(isoform_slice_options, colour_bar);
  FIELD(isoform_slice_options, height);
  FIELD(isoform_slice_options, colour);
  end();

  begin("isoform_boxes_options", sizeof(isoform_boxes_options));
  FIELD(isoform_boxes_options, q);
  FIELD(isoform_boxes_options, gap);
  FIELD(isoform_boxes_options, face_cells);
  FIELD(isoform_boxes_options, centroid_lines);
  FIELD(isoform_boxes_options, domain);
  FIELD(isoform_boxes_options, uvw_min);
  FIELD(isoform_boxes_options, uvw_max);
  FIELD(isoform_boxes_options, centre);
  FIELD(isoform_boxes_options, colour);
  end();

  begin("isoform_stack_options", sizeof(isoform_stack_options));
  FIELD(isoform_stack_options, n);
  FIELD(isoform_stack_options, transparency);
  FIELD(isoform_stack_options, view);
  FIELD(isoform_stack_options, colour);
  end();

  begin("isoform_reduce_options", sizeof(isoform_reduce_options));
  FIELD(isoform_reduce_options, keep_fraction);
  FIELD(isoform_reduce_options, tolerance);
  FIELD(isoform_reduce_options, lock_boundary);
  FIELD(isoform_reduce_options, point_method);
  FIELD(isoform_reduce_options, graph);
  FIELD(isoform_reduce_options, graph_rms_tolerance);
  FIELD(isoform_reduce_options, swaps);
  FIELD(isoform_reduce_options, measure_error);
  FIELD(isoform_reduce_options, refine_point);
  FIELD(isoform_reduce_options, vertex_fallback);
  FIELD(isoform_reduce_options, manifold_parts_only);
  FIELD(isoform_reduce_options, prevent_overlap);
  end();

  begin("isoform_reduce_stats", sizeof(isoform_reduce_stats));
  FIELD(isoform_reduce_stats, triangles_before);
  FIELD(isoform_reduce_stats, triangles_after);
  FIELD(isoform_reduce_stats, vertices_before);
  FIELD(isoform_reduce_stats, vertices_after);
  FIELD(isoform_reduce_stats, removals);
  FIELD(isoform_reduce_stats, swaps);
  FIELD(isoform_reduce_stats, vertex_points);
  FIELD(isoform_reduce_stats, passes);
  FIELD(isoform_reduce_stats, curvature_computed);
  FIELD(isoform_reduce_stats, stop_reason);
  FIELD(isoform_reduce_stats, max_distance);
  FIELD(isoform_reduce_stats, graph_rms);
  FIELD(isoform_reduce_stats, refused_corona);
  FIELD(isoform_reduce_stats, refused_half_plane);
  FIELD(isoform_reduce_stats, refused_flip);
  FIELD(isoform_reduce_stats, refused_nonmanifold);
  FIELD(isoform_reduce_stats, refused_boundary);
  FIELD(isoform_reduce_stats, refused_tolerance);
  FIELD(isoform_reduce_stats, parts_left_alone);
  FIELD(isoform_reduce_stats, triangles_left_alone);
  FIELD(isoform_reduce_stats, refused_overlap);
  FIELD(isoform_reduce_stats, kernel_points);
  end();

  begin("isoform_patch_options", sizeof(isoform_patch_options));
  FIELD(isoform_patch_options, blend);
  FIELD(isoform_patch_options, tension);
  FIELD(isoform_patch_options, edge_tension_count);
  FIELD(isoform_patch_options, edge_tension_vertices);
  FIELD(isoform_patch_options, edge_tension_values);
  end();

  begin("isoform_patch_stats", sizeof(isoform_patch_stats));
  FIELD(isoform_patch_stats, triangles);
  FIELD(isoform_patch_stats, edges);
  FIELD(isoform_patch_stats, nonconvex_edges);
  FIELD(isoform_patch_stats, opposite_normal_edges);
  FIELD(isoform_patch_stats, fallback_plane_edges);
  end();

  begin("isoform_compare_options", sizeof(isoform_compare_options));
  FIELD(isoform_compare_options, level);
  FIELD(isoform_compare_options, reference);
  FIELD(isoform_compare_options, fit_reference);
  FIELD(isoform_compare_options, centre);
  FIELD(isoform_compare_options, radius);
  FIELD(isoform_compare_options, minor_radius);
  FIELD(isoform_compare_options, grid);
  FIELD(isoform_compare_options, isovalue);
  FIELD(isoform_compare_options, loop_isolation);
  FIELD(isoform_compare_options, loop_sharp_corners);
  FIELD(isoform_compare_options, table_triangles);
  FIELD(isoform_compare_options, input_name);
  FIELD(isoform_compare_options, side_vertex);
  end();

  begin("isoform_compare_stats", sizeof(isoform_compare_stats));
  FIELD(isoform_compare_stats, count);
  FIELD(isoform_compare_stats, max);
  FIELD(isoform_compare_stats, rms);
  FIELD(isoform_compare_stats, mean);
  end();

  begin("isoform_compare_spread", sizeof(isoform_compare_spread));
  FIELD(isoform_compare_spread, count);
  FIELD(isoform_compare_spread, p05);
  FIELD(isoform_compare_spread, p50);
  FIELD(isoform_compare_spread, p95);
  FIELD(isoform_compare_spread, mean);
  FIELD(isoform_compare_spread, stddev);
  end();

  begin("isoform_compare_metrics", sizeof(isoform_compare_metrics));
  FIELD(isoform_compare_metrics, samples);
  FIELD(isoform_compare_metrics, failed_samples);
  FIELD(isoform_compare_metrics, deviation);
  FIELD(isoform_compare_metrics, data_point_error);
  FIELD(isoform_compare_metrics, normal_gap);
  FIELD(isoform_compare_metrics, position_gap);
  FIELD(isoform_compare_metrics, mean_curvature_jump);
  FIELD(isoform_compare_metrics, mean_curvature_error);
  FIELD(isoform_compare_metrics, mean_curvature);
  FIELD(isoform_compare_metrics, gauss_curvature);
  FIELD(isoform_compare_metrics, evaluation_seconds);
  FIELD(isoform_compare_metrics, seconds_per_million);
  FIELD(isoform_compare_metrics, tessellation_triangles);
  end();

  printf("\n}}\n");
  return 0;
}
