// Shared mesh-building steps of the Chapter 2 meshes.
#include "mesh_build.h"

#include <cmath>

namespace isoform::visualize {

void append_mesh(Mesh& into, const Mesh& part) {
  const int32_t offset = int32_t(into.vertex_count());
  const bool normals = !part.normals.empty() && (into.points.empty() || !into.normals.empty());
  into.points.insert(into.points.end(), part.points.begin(), part.points.end());
  into.colors.insert(into.colors.end(), part.colors.begin(), part.colors.end());
  if (normals)
    into.normals.insert(into.normals.end(), part.normals.begin(), part.normals.end());
  else
    into.normals.clear();
  for (int32_t v : part.triangles) into.triangles.push_back(v + offset);
  for (int32_t v : part.edges) into.edges.push_back(v + offset);
}

void add_vertex(Mesh& mesh, const Vec3d& p, const std::array<uint8_t, 4>& rgba) {
  for (int a = 0; a < 3; ++a) mesh.points.push_back(float(p[a]));
  mesh.colors.insert(mesh.colors.end(), rgba.begin(), rgba.end());
}

void add_grid_triangles(Mesh& mesh, int32_t first, int nu, int nv, bool flip) {
  for (int j = 0; j + 1 < nv; ++j)
    for (int i = 0; i + 1 < nu; ++i) {
      const int32_t a = first + j * nu + i, b = a + 1, c = a + nu + 1, d = a + nu;
      if (!flip)
        mesh.triangles.insert(mesh.triangles.end(), {a, b, c, a, c, d});
      else
        mesh.triangles.insert(mesh.triangles.end(), {a, c, b, a, d, c});
    }
}

void add_grid_edges(Mesh& mesh, int32_t first, int nu, int nv) {
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i + 1 < nu; ++i) mesh.edges.insert(mesh.edges.end(), {first + j * nu + i, first + j * nu + i + 1});
  for (int j = 0; j + 1 < nv; ++j)
    for (int i = 0; i < nu; ++i) mesh.edges.insert(mesh.edges.end(), {first + j * nu + i, first + (j + 1) * nu + i});
}

void compute_vertex_normals(Mesh& mesh, const Vec3d& fallback) {
  std::vector<double> sum(mesh.points.size(), 0.0);
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const int32_t* v = &mesh.triangles[3 * t];
    double e1[3], e2[3];
    for (int a = 0; a < 3; ++a) {
      e1[a] = double(mesh.points[3 * v[1] + a]) - mesh.points[3 * v[0] + a];
      e2[a] = double(mesh.points[3 * v[2] + a]) - mesh.points[3 * v[0] + a];
    }
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                         e1[0] * e2[1] - e1[1] * e2[0]};
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) sum[3 * size_t(v[k]) + a] += n[a];
  }
  mesh.normals.resize(mesh.points.size());
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const double* n = &sum[3 * v];
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int a = 0; a < 3; ++a)
      mesh.normals[3 * v + a] = float(length > 0.0 ? n[a] / length : fallback[a]);
  }
}

}  // namespace isoform::visualize
