#include "compare_meshes.h"

#include <cmath>

#include "libcore/mesh_normals.h"
#include "libcore/topology.h"

namespace isoform::test {
namespace {

Mesh finish(std::vector<double> points, std::vector<int32_t> triangles) {
  Mesh m;
  m.precise_points = std::move(points);
  m.points.assign(m.precise_points.begin(), m.precise_points.end());
  m.triangles = std::move(triangles);
  compute_topology(m);
  estimate_normals(m);
  return m;
}

}  // namespace

Mesh octahedron() {
  return finish({1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1},
                {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5});
}

Mesh icosahedron(double jitter) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<double> p = {-1, g, 0, 1, g, 0, -1, -g, 0, 1, -g, 0, 0, -1, g, 0, 1, g,
                           0, -1, -g, 0, 1, -g, g, 0, -1, g, 0, 1, -g, 0, -1, -g, 0, 1};
  const double s = 1.0 / std::sqrt(1.0 + g * g);
  for (size_t i = 0; i < p.size(); ++i) p[i] = p[i] * s + jitter * std::sin(12.9898 * double(i + 1) + 0.7);
  return finish(std::move(p), {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,
                               11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8,
                               3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1});
}

Mesh regular_torus(int m, int n, double R, double r) {
  const double pi = 3.14159265358979323846;
  std::vector<double> p;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = 2 * pi * i / m, b = 2 * pi * j / n;
      p.insert(p.end(), {(R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b)});
    }
  std::vector<int32_t> t;
  auto id = [&](int i, int j) { return int32_t(((i + m) % m) * n + (j + n) % n); };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      t.insert(t.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.insert(t.end(), {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return finish(std::move(p), std::move(t));
}

std::array<double, 3> vertex(const Mesh& mesh, int v) {
  const size_t i = 3 * size_t(v);
  return {mesh.precise_points[i], mesh.precise_points[i + 1], mesh.precise_points[i + 2]};
}

}  // namespace isoform::test
