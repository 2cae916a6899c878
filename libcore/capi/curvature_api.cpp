// The C API's surface curvature calls (Section 4.2) and vertex colours.
#include <cstring>

#include "../curvature/curvature_colours.h"
#include "../curvature/surface_curvature.h"
#include "../errors.h"
#include "../mesh_normals.h"
#include "../progress.h"
#include "handles.h"

using isoform::capi::fail;
using isoform::capi::guarded;

namespace {

isoform::CurvatureOptions to_options(const isoform_curvature_options& o) {
  isoform::CurvatureOptions c;
  if (o.method < ISOFORM_CURVATURE_SEED || o.method > ISOFORM_CURVATURE_QUARTIC)
    throw isoform::InvalidArgument("isoform_curvature: unknown method " + std::to_string(o.method));
  if (o.color_by < ISOFORM_CURVATURE_K1 || o.color_by > ISOFORM_CURVATURE_ABSOLUTE)
    throw isoform::InvalidArgument("isoform_curvature: color_by must be a scalar quantity (0 to 4), not " +
                                   std::to_string(o.color_by));
  if (o.threads < 0) throw isoform::InvalidArgument("isoform_curvature: threads must not be negative");
  c.method = isoform::CurvatureMethod(o.method);
  c.extra_rings = o.extra_rings;
  c.update_normals = o.update_normals != 0;
  c.threads = o.threads;
  return c;
}

}  // namespace

extern "C" {

void isoform_curvature_options_default(isoform_curvature_options* options) {
  if (!options) return;
  std::memset(options, 0, sizeof(*options));
  options->method = ISOFORM_CURVATURE_QUARTIC;
  options->color_by = ISOFORM_CURVATURE_MEAN;
}

isoform_status isoform_curvature(isoform_mesh* mesh, const isoform_curvature_options* options,
                                 isoform_progress* progress) {
  return guarded([&] {
    if (!mesh) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_curvature: NULL mesh");
    isoform_curvature_options o;
    isoform_curvature_options_default(&o);
    if (options) o = *options;
    const isoform::CurvatureOptions c = to_options(o);
    const isoform::Progress p(progress);
    p.stage(ISOFORM_STAGE_CURVATURE);
    // The fit reads the mesh and writes new arrays, which replace the
    // mesh's only once everything has succeeded: a failure leaves the mesh
    // as it was. Only a mesh without normals is copied, to estimate them.
    isoform::Mesh& m = mesh->mesh;
    const isoform::Mesh* input = &m;
    isoform::Mesh with_normals;
    if (m.normals.size() != m.points.size()) {
      with_normals.points = m.points;
      with_normals.precise_points = m.precise_points;
      with_normals.triangles = m.triangles;
      isoform::estimate_normals(with_normals);
      input = &with_normals;
    }
    isoform::VertexCurvature curvature;
    std::vector<float> fitted_normals;
    isoform::compute_curvature(*input, c, p, curvature, &fitted_normals);
    const auto q = isoform::CurvatureQuantity(o.color_by);
    std::vector<uint8_t> colors;
    double lo = 0, hi = 0;
    isoform::curvature_colours(curvature, q, colors, &lo, &hi);
    m.curvature = std::move(curvature);
    m.colors = std::move(colors);
    if (c.update_normals)
      m.normals = std::move(fitted_normals);
    else if (input == &with_normals)
      m.normals = std::move(with_normals.normals);
    mesh->curvature_color_by = o.color_by;
    mesh->curvature_color_range[0] = lo;
    mesh->curvature_color_range[1] = hi;
    p.stage(ISOFORM_STAGE_DONE);
    return ISOFORM_OK;
  });
}

int isoform_mesh_has_curvature(const isoform_mesh* mesh) {
  return mesh && !mesh->mesh.curvature.empty() ? 1 : 0;
}

isoform_status isoform_mesh_curvature_stats(const isoform_mesh* mesh, isoform_curvature_stats* out) {
  return guarded([&] {
    if (!mesh || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_curvature_stats: NULL argument");
    const isoform::VertexCurvature& c = mesh->mesh.curvature;
    if (c.empty() && mesh->mesh.vertex_count() > 0)
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_curvature_stats: the mesh has no curvature");
    std::memset(out, 0, sizeof(*out));
    const isoform::CurvatureStats& s = c.stats;
    out->method = int(s.method);
    out->color_by = mesh->curvature_color_by;
    out->vertices = s.vertices;
    out->boundary = s.boundary;
    out->widened = s.widened;
    out->lower_order = s.lower_order;
    out->nonmanifold = s.nonmanifold;
    out->isolated = s.isolated;
    out->failed = s.failed;
    out->normal_repaired = s.normal_repaired;
    out->color_min = mesh->curvature_color_range[0];
    out->color_max = mesh->curvature_color_range[1];
    return ISOFORM_OK;
  });
}

isoform_status isoform_mesh_copy_curvature(const isoform_mesh* mesh, int quantity, float* out) {
  return guarded([&] {
    if (!mesh || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_copy_curvature: NULL argument");
    const isoform::VertexCurvature& c = mesh->mesh.curvature;
    if (c.empty() && mesh->mesh.vertex_count() > 0)
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_copy_curvature: the mesh has no curvature");
    const std::vector<float>* v = nullptr;
    switch (quantity) {
      case ISOFORM_CURVATURE_K1: v = &c.k1; break;
      case ISOFORM_CURVATURE_K2: v = &c.k2; break;
      case ISOFORM_CURVATURE_MEAN: v = &c.mean; break;
      case ISOFORM_CURVATURE_GAUSS: v = &c.gauss; break;
      case ISOFORM_CURVATURE_ABSOLUTE: v = &c.absolute; break;
      case ISOFORM_CURVATURE_DIR1: v = &c.d1; break;
      case ISOFORM_CURVATURE_DIR2: v = &c.d2; break;
      default:
        return fail(ISOFORM_ERR_INVALID_ARGUMENT,
                    "isoform_mesh_copy_curvature: unknown quantity " + std::to_string(quantity));
    }
    if (!v->empty()) std::memcpy(out, v->data(), v->size() * sizeof(float));
    return ISOFORM_OK;
  });
}

isoform_status isoform_mesh_copy_curvature_flags(const isoform_mesh* mesh, uint8_t* out) {
  return guarded([&] {
    if (!mesh || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_copy_curvature_flags: NULL argument");
    const std::vector<uint8_t>& f = mesh->mesh.curvature.flags;
    if (f.empty() && mesh->mesh.vertex_count() > 0)
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_copy_curvature_flags: the mesh has no curvature");
    if (!f.empty()) std::memcpy(out, f.data(), f.size());
    return ISOFORM_OK;
  });
}

}  // extern "C"
