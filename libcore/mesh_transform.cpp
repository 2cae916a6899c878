// A mesh moved by an affine map (see mesh_transform.h).
#include "mesh_transform.h"

#include <cmath>
#include <utility>

#include "errors.h"

namespace isoform {

namespace {

// True when the linear part's columns are orthonormal (within rounding).
bool is_rigid(const Affine& map) {
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double dot = 0;
      for (int r = 0; r < 3; ++r) dot += map.m[r][a] * map.m[r][b];
      if (std::fabs(dot - (a == b ? 1.0 : 0.0)) > 1e-9) return false;
    }
  return true;
}

Vec3d unit(const Vec3d& v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return n > 0 ? Vec3d{v[0] / n, v[1] / n, v[2] / n} : v;
}

template <class Real, class Map>
void map_triples(std::vector<Real>& values, Map&& map) {
  for (size_t i = 0; i + 2 < values.size(); i += 3) {
    const Vec3d v = map(Vec3d{double(values[i]), double(values[i + 1]), double(values[i + 2])});
    for (int a = 0; a < 3; ++a) values[i + size_t(a)] = Real(v[size_t(a)]);
  }
}

}  // namespace

void transform_mesh(Mesh& mesh, const Affine& map) {
  for (const auto& row : map.m)
    for (double v : row)
      if (!std::isfinite(v)) throw InvalidArgument("the map holds a value that is not finite");
  const double det = map.determinant();
  if (det == 0.0) throw InvalidArgument("the map flattens space (its determinant is 0)");
  map_triples(mesh.points, [&](const Vec3d& p) { return map.apply(p); });
  map_triples(mesh.precise_points, [&](const Vec3d& p) { return map.apply(p); });
  map_triples(mesh.normals, [&](const Vec3d& n) { return unit(map.apply_normal(n)); });
  if (det < 0) {
    // (v0, v1, v2) becomes (v0, v2, v1): its edges (v0 v2), (v2 v1), (v1 v0)
    // were edges 2, 1 and 0.
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      std::swap(mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]);
      if (mesh.neighbours.size() == mesh.triangles.size()) std::swap(mesh.neighbours[3 * t], mesh.neighbours[3 * t + 2]);
    }
  }
  VertexCurvature& c = mesh.curvature;
  if (c.empty()) return;
  if (!is_rigid(map)) {
    c = VertexCurvature{};
    return;
  }
  // Principal directions are tangent vectors; with a mirror the pair keeps
  // k1 >= k2 and the curvature signs (outward normals stay outward).
  // A mirror would turn d1 x d2 against the normal: d2 is turned back.
  const double flip = det < 0 ? -1.0 : 1.0;
  map_triples(c.d1, [&](const Vec3d& d) { return map.apply_linear(d); });
  map_triples(c.d2, [&](const Vec3d& d) {
    const Vec3d v = map.apply_linear(d);
    return Vec3d{flip * v[0], flip * v[1], flip * v[2]};
  });
}

}  // namespace isoform
