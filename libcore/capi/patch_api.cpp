// The C API's side-vertex surface calls (Hamann 1991, Chapter 6).
#include <atomic>
#include <cmath>
#include <cstring>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "../errors.h"
#include "../patch/side_vertex_surface.h"
#include "../patch/tessellate.h"
#include "../progress.h"
#include "handles.h"

using isoform::capi::fail;
using isoform::capi::guarded;

struct isoform_patch {
  std::unique_ptr<isoform::patch::SideVertexSurface> surface;
};

namespace {

isoform::patch::PatchOptions to_options(const isoform_patch_options& o) {
  isoform::patch::PatchOptions p;
  if (o.blend != ISOFORM_PATCH_BLEND_PRINTED && o.blend != ISOFORM_PATCH_BLEND_SQUARED)
    throw isoform::InvalidArgument("isoform_patch_create: unknown blend " + std::to_string(o.blend));
  p.blend = isoform::patch::Blend(o.blend);
  p.tension = o.tension;
  if (o.edge_tension_count && (!o.edge_tension_vertices || !o.edge_tension_values))
    throw isoform::InvalidArgument("isoform_patch_create: edge_tension_count is set but an edge array is NULL");
  for (size_t e = 0; e < o.edge_tension_count; ++e)
    p.edge_tension.push_back(
        {o.edge_tension_vertices[2 * e], o.edge_tension_vertices[2 * e + 1], o.edge_tension_values[e]});
  return p;
}

// The message of a bad sample k.
std::string sample_name(size_t k, int32_t t, double u, double v) {
  return "isoform_patch_evaluate: sample " + std::to_string(k) + " (triangle " + std::to_string(t) + ", u " +
         std::to_string(u) + ", v " + std::to_string(v) + ")";
}

}  // namespace

extern "C" {

void isoform_patch_options_default(isoform_patch_options* options) {
  if (!options) return;
  std::memset(options, 0, sizeof(*options));
  options->blend = ISOFORM_PATCH_BLEND_SQUARED;
}

isoform_status isoform_patch_create(const isoform_mesh* mesh, const isoform_patch_options* options,
                                    isoform_patch** out) {
  return guarded([&] {
    if (!mesh || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_patch_create: NULL argument");
    *out = nullptr;
    isoform_patch_options o;
    isoform_patch_options_default(&o);
    if (options) o = *options;
    auto patch = std::make_unique<isoform_patch>();
    patch->surface = std::make_unique<isoform::patch::SideVertexSurface>(mesh->mesh, to_options(o));
    *out = patch.release();
    return ISOFORM_OK;
  });
}

void isoform_patch_free(isoform_patch* patch) { delete patch; }

isoform_status isoform_patch_stats_get(const isoform_patch* patch, isoform_patch_stats* out) {
  return guarded([&] {
    if (!patch || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_patch_stats_get: NULL argument");
    const isoform::patch::PatchStats& s = patch->surface->stats();
    std::memset(out, 0, sizeof(*out));
    out->triangles = (long long)patch->surface->triangle_count();
    out->edges = s.edges;
    out->nonconvex_edges = s.nonconvex_edges;
    out->opposite_normal_edges = s.opposite_normal_edges;
    out->fallback_plane_edges = s.fallback_plane_edges;
    return ISOFORM_OK;
  });
}

isoform_status isoform_patch_evaluate(const isoform_patch* patch, size_t count, const int32_t* triangles,
                                      const double* uv, double* points, double* normals) {
  return guarded([&] {
    if (!patch || (count && (!triangles || !uv)))
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_patch_evaluate: NULL argument");
    const isoform::patch::SideVertexSurface& s = *patch->surface;
    // Phase 1: check every sample (cheap, serial: the first bad one is named).
    for (size_t k = 0; k < count; ++k) {
      const int32_t t = triangles[k];
      const double u = uv[2 * k], v = uv[2 * k + 1];
      if (t < 0 || size_t(t) >= s.triangle_count())
        return fail(ISOFORM_ERR_INVALID_ARGUMENT, sample_name(k, t, u, v) + ": no such triangle (the mesh has " +
                                                      std::to_string(s.triangle_count()) + ")");
      if (!(u >= 0.0) || !(v >= 0.0) || !(u + v <= 1.0 + 1e-12))
        return fail(ISOFORM_ERR_INVALID_ARGUMENT, sample_name(k, t, u, v) + ": outside the triangle");
    }
    // Phase 2: evaluate in parallel; remember the first undefined sample.
    std::atomic<size_t> first_bad{count};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 1024), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t k = r.begin(); k < r.end(); ++k) {
        isoform::SurfaceSample x;
        if (!s.evaluate_order(size_t(triangles[k]), uv[2 * k], uv[2 * k + 1], x, false)) {
          size_t seen = first_bad.load();
          while (k < seen && !first_bad.compare_exchange_weak(seen, k)) {
          }
          continue;
        }
        for (int a = 0; a < 3; ++a) {
          if (points) points[3 * k + a] = x.point[a];
          if (normals) normals[3 * k + a] = x.normal[a];
        }
      }
    });
    if (first_bad < count) {
      const size_t k = first_bad;
      return fail(ISOFORM_ERR_INVALID_ARGUMENT,
                  sample_name(k, triangles[k], uv[2 * k], uv[2 * k + 1]) + ": the surface is undefined there");
    }
    return ISOFORM_OK;
  });
}

isoform_status isoform_patch_tessellate(const isoform_patch* patch, int level, isoform_progress* progress,
                                        isoform_mesh** out) {
  return guarded([&] {
    if (!patch || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_patch_tessellate: NULL argument");
    *out = nullptr;
    const isoform::Progress p(progress);
    p.stage(ISOFORM_STAGE_PATCH);
    auto mesh = std::make_unique<isoform_mesh>();
    mesh->mesh = isoform::patch::tessellate(*patch->surface, level, p);
    p.stage(ISOFORM_STAGE_DONE);
    *out = mesh.release();
    return ISOFORM_OK;
  });
}

}  // extern "C"
