// The C API's mesh calls: statistics, copy-out, arrays in, files.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

#include "../errors.h"
#include "../mesh_normals.h"
#include "../mesh_transform.h"
#include "../part_filter.h"
#include "../meshio/meshio.h"
#include "../topology.h"
#include "handles.h"

using isoform::capi::fail;
using isoform::capi::guarded;

namespace {

void bounding_box(const isoform::Mesh& m, isoform_mesh_stats* out) {
  for (int a = 0; a < 3; ++a) {
    out->bbox_min[a] = m.points.empty() ? 0.0 : HUGE_VAL;
    out->bbox_max[a] = m.points.empty() ? 0.0 : -HUGE_VAL;
  }
  for (size_t i = 0; i < m.points.size(); ++i) {
    const int a = int(i % 3);
    out->bbox_min[a] = std::min(out->bbox_min[a], double(m.points[i]));
    out->bbox_max[a] = std::max(out->bbox_max[a], double(m.points[i]));
  }
}

// Checks triangle indices, then computes neighbours, parts and normals.
void finish(isoform::Mesh& m, const std::string& what) {
  const size_t n = m.vertex_count();
  for (size_t i = 0; i < m.triangles.size(); ++i)
    if (m.triangles[i] < 0 || size_t(m.triangles[i]) >= n)
      throw isoform::InvalidArgument(what + ": triangle " + std::to_string(i / 3) + " refers to vertex " +
                                     std::to_string(m.triangles[i]) + " but there are " + std::to_string(n) +
                                     " vertices");
  for (size_t i = 0; i < m.points.size(); ++i)
    if (!std::isfinite(m.points[i]))
      throw isoform::FormatError(what + ": vertex " + std::to_string(i / 3) + " has a coordinate that is NaN or infinite");
  isoform::compute_topology(m);
  if (m.normals.size() != m.points.size()) isoform::estimate_normals(m);
}

template <class T>
isoform_status copy_out(const isoform_mesh* mesh, T* out, const std::vector<T>& (*pick)(const isoform::Mesh&),
                        const char* what) {
  return guarded([&] {
    if (!mesh || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, std::string(what) + ": NULL argument");
    const std::vector<T>& v = pick(mesh->mesh);
    if (!v.empty()) std::memcpy(out, v.data(), v.size() * sizeof(T));
    return ISOFORM_OK;
  });
}

// Points of either precision; double ones are also kept for curvature fits.
template <class Real>
isoform_status mesh_from_arrays(const Real* points, size_t n, const int32_t* triangles, size_t m,
                                isoform_mesh** out, const char* what) {
  return guarded([&] {
    if (!out || (n && !points) || (m && !triangles))
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, std::string(what) + ": NULL argument");
    *out = nullptr;
    auto mesh = std::make_unique<isoform_mesh>();
    mesh->mesh.points.assign(points, points + 3 * n);
    if (sizeof(Real) == sizeof(double)) {
      mesh->mesh.precise_points.assign(points, points + 3 * n);
      for (size_t i = 0; i < mesh->mesh.precise_points.size(); ++i)
        if (!std::isfinite(mesh->mesh.precise_points[i]))
          throw isoform::FormatError(std::string(what) + ": vertex " + std::to_string(i / 3) +
                                     " has a coordinate that is NaN or infinite");
    }
    mesh->mesh.triangles.assign(triangles, triangles + 3 * m);
    finish(mesh->mesh, what);
    mesh->normals_estimated = true;
    *out = mesh.release();
    return ISOFORM_OK;
  });
}

const std::vector<float>& points_of(const isoform::Mesh& m) { return m.points; }
const std::vector<float>& normals_of(const isoform::Mesh& m) { return m.normals; }
const std::vector<int32_t>& triangles_of(const isoform::Mesh& m) { return m.triangles; }
const std::vector<int32_t>& neighbours_of(const isoform::Mesh& m) { return m.neighbours; }
const std::vector<int32_t>& parts_of(const isoform::Mesh& m) { return m.parts; }

}  // namespace

extern "C" {

isoform_status isoform_mesh_stats_get(const isoform_mesh* mesh, isoform_mesh_stats* out) {
  return guarded([&] {
    if (!mesh || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_stats_get: NULL argument");
    const isoform::Mesh& m = mesh->mesh;
    std::memset(out, 0, sizeof(*out));
    out->vertices = (long long)m.vertex_count();
    out->triangles = (long long)m.triangle_count();
    out->parts = m.part_count;
    out->boundary_edges = m.stats.boundary_edges;
    out->nonmanifold_edges = m.stats.nonmanifold_edges;
    out->inconsistent_edges = m.stats.inconsistent_edges;
    out->degenerate_triangles = m.stats.degenerate_triangles;
    out->euler_characteristic = m.stats.euler_characteristic;
    out->isovalue = m.contour.isovalue;
    out->isovalue_was_auto = m.contour.isovalue_was_auto;
    out->ambiguous_faces = m.contour.ambiguous_faces;
    out->degenerate_saddles = m.contour.degenerate_saddles;
    out->extra_points = m.contour.extra_points;
    out->centroid_points = m.contour.centroid_points;
    out->near_sample_points = m.contour.near_sample_points;
    bounding_box(m, out);
    return ISOFORM_OK;
  });
}

size_t isoform_mesh_vertex_count(const isoform_mesh* mesh) { return mesh ? mesh->mesh.vertex_count() : 0; }
size_t isoform_mesh_triangle_count(const isoform_mesh* mesh) { return mesh ? mesh->mesh.triangle_count() : 0; }
size_t isoform_mesh_part_count(const isoform_mesh* mesh) { return mesh ? size_t(mesh->mesh.part_count) : 0; }

isoform_status isoform_mesh_copy_points(const isoform_mesh* mesh, float* out) {
  return copy_out(mesh, out, points_of, "isoform_mesh_copy_points");
}
isoform_status isoform_mesh_copy_normals(const isoform_mesh* mesh, float* out) {
  return copy_out(mesh, out, normals_of, "isoform_mesh_copy_normals");
}
isoform_status isoform_mesh_copy_triangles(const isoform_mesh* mesh, int32_t* out) {
  return copy_out(mesh, out, triangles_of, "isoform_mesh_copy_triangles");
}
isoform_status isoform_mesh_copy_neighbours(const isoform_mesh* mesh, int32_t* out) {
  return copy_out(mesh, out, neighbours_of, "isoform_mesh_copy_neighbours");
}
isoform_status isoform_mesh_copy_parts(const isoform_mesh* mesh, int32_t* out) {
  return copy_out(mesh, out, parts_of, "isoform_mesh_copy_parts");
}

isoform_status isoform_mesh_from_arrays(const float* points, size_t n, const int32_t* triangles, size_t m,
                                        isoform_mesh** out) {
  return mesh_from_arrays(points, n, triangles, m, out, "isoform_mesh_from_arrays");
}

isoform_status isoform_mesh_from_arrays_f64(const double* points, size_t n, const int32_t* triangles, size_t m,
                                            isoform_mesh** out) {
  return mesh_from_arrays(points, n, triangles, m, out, "isoform_mesh_from_arrays_f64");
}

isoform_status isoform_mesh_set_normals(isoform_mesh* mesh, const float* normals) {
  return guarded([&] {
    if (!mesh || (!normals && mesh->mesh.vertex_count() > 0))
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_set_normals: NULL argument");
    const size_t n = mesh->mesh.vertex_count();
    std::vector<float> unit(normals, normals + 3 * n);
    for (size_t v = 0; v < n; ++v) {
      float* q = &unit[3 * v];
      const double len = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] + double(q[2]) * q[2]);
      if (!std::isfinite(len) || !(len > 0.0))
        return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_set_normals: normal " + std::to_string(v) +
                                                      " is zero or not finite");
      for (int a = 0; a < 3; ++a) q[a] = float(q[a] / len);
    }
    mesh->mesh.normals = std::move(unit);
    mesh->normals_estimated = false;
    return ISOFORM_OK;
  });
}

isoform_status isoform_mesh_load(const char* path, isoform_mesh** out) {
  return guarded([&] {
    if (!path || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_load: NULL argument");
    *out = nullptr;
    auto mesh = std::make_unique<isoform_mesh>();
    mesh->mesh = isoform::load_mesh(path);
    mesh->normals_estimated = mesh->mesh.normals.size() != mesh->mesh.points.size();
    finish(mesh->mesh, path);
    *out = mesh.release();
    return ISOFORM_OK;
  });
}

isoform_status isoform_mesh_save(const isoform_mesh* mesh, const char* path) {
  return isoform_mesh_save_progress(mesh, path, nullptr);
}

isoform_status isoform_mesh_save_progress(const isoform_mesh* mesh, const char* path, isoform_progress* progress) {
  return guarded([&] {
    if (!mesh || !path) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_save: NULL argument");
    isoform::save_mesh(mesh->mesh, path, isoform::Progress(progress));
    return ISOFORM_OK;
  });
}

void isoform_mesh_free(isoform_mesh* mesh) { delete mesh; }

int isoform_mesh_normals_estimated(const isoform_mesh* mesh) { return mesh && mesh->normals_estimated ? 1 : 0; }

}  // extern "C"

extern "C" {

void isoform_part_filter_default(isoform_part_filter* filter) {
  if (!filter) return;
  *filter = isoform_part_filter{};
  filter->struct_size = sizeof *filter;
}

isoform_status isoform_mesh_filter_parts(isoform_mesh* mesh, const isoform_part_filter* filter,
                                         isoform_part_filter_stats* stats) {
  return guarded([&] {
    const char* what = "isoform_mesh_filter_parts";
    if (!mesh || !filter) return fail(ISOFORM_ERR_INVALID_ARGUMENT, std::string(what) + ": NULL argument");
    if (filter->struct_size < offsetof(isoform_part_filter, largest) + sizeof(long long))
      return fail(ISOFORM_ERR_INVALID_ARGUMENT,
                  std::string(what) + ": filter.struct_size is not set (call isoform_part_filter_default)");
    isoform_part_filter known;
    isoform_part_filter_default(&known);
    std::memcpy(&known, filter, std::min(filter->struct_size, sizeof known));
    if (known.min_triangles < 0 || known.largest < 0 || !(known.min_volume >= 0) || std::isinf(known.min_volume))
      return fail(ISOFORM_ERR_INVALID_ARGUMENT,
                  std::string(what) + ": min_triangles, min_volume and largest must be finite and not negative");
    isoform::PartFilter f;
    f.min_triangles = known.min_triangles;
    f.min_volume = known.min_volume;
    f.largest = known.largest;
    const isoform::PartFilterResult r = isoform::filter_parts(mesh->mesh, f);
    if (stats) {
      stats->parts_before = r.parts_before;
      stats->parts_after = r.parts_after;
      stats->triangles_before = r.triangles_before;
      stats->triangles_after = r.triangles_after;
    }
    return ISOFORM_OK;
  });
}

isoform_status isoform_mesh_transform(isoform_mesh* mesh, const double matrix[16]) {
  return guarded([&] {
    if (!mesh || !matrix) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_transform: NULL argument");
    if (matrix[12] != 0 || matrix[13] != 0 || matrix[14] != 0 || matrix[15] != 1)
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_transform: the last row must be 0 0 0 1");
    isoform::Affine map;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) map.m[r][c] = matrix[4 * r + c];
    try {
      isoform::transform_mesh(mesh->mesh, map);
    } catch (const isoform::InvalidArgument& e) {
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, std::string("isoform_mesh_transform: ") + e.what());
    }
    return ISOFORM_OK;
  });
}

}  // extern "C"
