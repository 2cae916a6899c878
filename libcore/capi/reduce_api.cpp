// The C API's reduction calls (Chapter 5).
#include <cstring>

#include "../errors.h"
#include "../progress.h"
#include "../reduce/reduce.h"
#include "handles.h"

using isoform::capi::fail;
using isoform::capi::guarded;

namespace {

isoform::ReduceOptions to_options(const isoform_reduce_options& o) {
  if (o.point_method != ISOFORM_REDUCE_POINT_QUADRATIC && o.point_method != ISOFORM_REDUCE_POINT_QUADRIC)
    throw isoform::InvalidArgument("isoform_reduce: unknown point_method " + std::to_string(o.point_method));
  isoform::ReduceOptions r;
  r.keep_fraction = o.keep_fraction;
  r.tolerance = o.tolerance;
  r.lock_boundary = o.lock_boundary != 0;
  r.point = isoform::ReducePoint(o.point_method);
  r.graph = o.graph != 0;
  r.graph_rms_tolerance = o.graph_rms_tolerance;
  r.swaps = o.swaps != 0;
  r.measure_error = o.measure_error != 0;
  r.refine_point = o.refine_point != 0;
  r.vertex_fallback = o.vertex_fallback != 0;
  r.manifold_parts_only = o.manifold_parts_only != 0;
  r.prevent_overlap = o.prevent_overlap != 0;
  return r;
}

isoform_reduce_stats to_stats(const isoform::ReduceStats& s) {
  isoform_reduce_stats o;
  std::memset(&o, 0, sizeof(o));
  o.triangles_before = s.triangles_before;
  o.triangles_after = s.triangles_after;
  o.vertices_before = s.vertices_before;
  o.vertices_after = s.vertices_after;
  o.removals = s.removals;
  o.swaps = s.swaps;
  o.vertex_points = s.vertex_points;
  o.kernel_points = s.kernel_points;
  o.passes = s.passes;
  o.curvature_computed = s.curvature_computed ? 1 : 0;
  o.stop_reason = s.stop_reason;
  o.max_distance = s.max_distance;
  o.graph_rms = s.graph_rms;
  o.refused_corona = s.refused.corona;
  o.refused_half_plane = s.refused.half_plane;
  o.refused_flip = s.refused.flip;
  o.refused_nonmanifold = s.refused.nonmanifold;
  o.refused_boundary = s.refused.boundary;
  o.refused_tolerance = s.refused.tolerance;
  o.parts_left_alone = s.parts_left_alone;
  o.triangles_left_alone = s.triangles_left_alone;
  o.refused_overlap = s.refused.overlap;
  return o;
}

}  // namespace

extern "C" {

void isoform_reduce_options_default(isoform_reduce_options* options) {
  if (!options) return;
  std::memset(options, 0, sizeof(*options));
  options->keep_fraction = 0.1;
  options->point_method = ISOFORM_REDUCE_POINT_QUADRATIC;
  options->swaps = 1;
  options->refine_point = 1;
  options->vertex_fallback = 1;
}

isoform_status isoform_reduce(isoform_mesh* mesh, const isoform_reduce_options* options,
                              isoform_progress* progress) {
  return guarded([&] {
    if (!mesh) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_reduce: NULL mesh");
    isoform_reduce_options o;
    isoform_reduce_options_default(&o);
    if (options) o = *options;
    const isoform::ReduceOptions r = to_options(o);
    const isoform::Progress p(progress);
    // reduce_mesh leaves the mesh as it was when it throws.
    isoform::ReduceStats s = isoform::reduce_mesh(mesh->mesh, r, p);
    mesh->reduced = true;
    mesh->reduce_stats = to_stats(s);
    mesh->reduce_left_alone = std::move(s.left_alone);
    p.stage(ISOFORM_STAGE_DONE);
    return ISOFORM_OK;
  });
}

isoform_status isoform_mesh_reduce_stats(const isoform_mesh* mesh, isoform_reduce_stats* out) {
  return guarded([&] {
    if (!mesh || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_reduce_stats: NULL argument");
    if (!mesh->reduced)
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_reduce_stats: the mesh was never reduced");
    *out = mesh->reduce_stats;
    return ISOFORM_OK;
  });
}

const char* isoform_mesh_reduce_left_alone(const isoform_mesh* mesh, long long index) {
  if (!mesh || index < 0 || index >= (long long)mesh->reduce_left_alone.size()) return nullptr;
  return mesh->reduce_left_alone[size_t(index)].c_str();
}

}  // extern "C"
