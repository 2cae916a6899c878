#include "mesh_checks.h"

#include <cmath>
#include <map>
#include <utility>

namespace isoform::test {

std::shared_ptr<const ScalarGrid> dense_grid(const Index3& n, std::vector<float> values, GridClass cls) {
  DenseVolume vol("f", cls, std::move(values), n, Affine());
  return vol.load(0);
}

std::shared_ptr<const ScalarGrid> dense_grid(const Index3& n, const std::function<double(int, int, int)>& f,
                                             GridClass cls) {
  std::vector<float> v(size_t(n[0]) * n[1] * n[2]);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) v[(size_t(k) * n[1] + j) * n[0] + i] = float(f(i, j, k));
  return dense_grid(n, std::move(v), cls);
}

Mesh run_contour(const ScalarGrid& grid, double iso, ContourMethod method, int threads) {
  ContourOptions o;
  o.isovalue = iso;
  o.auto_isovalue = false;
  o.method = method;
  o.threads = threads;
  return contour(grid, o, Progress(nullptr));
}

long long interior_boundary_edges(const Mesh& mesh, const Index3& n) {
  std::map<std::pair<int32_t, int32_t>, int> count;
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) {
      int32_t a = mesh.triangles[3 * t + i], b = mesh.triangles[3 * t + (i + 1) % 3];
      if (a > b) std::swap(a, b);
      ++count[{a, b}];
    }
  long long bad = 0;
  for (const auto& [edge, c] : count) {
    if (c != 1) continue;
    const float* p = &mesh.points[3 * size_t(edge.first)];
    const float* q = &mesh.points[3 * size_t(edge.second)];
    bool on_same_face = false;
    for (int a = 0; a < 3; ++a)
      for (double plane : {0.0, double(n[a] - 1)})
        on_same_face |= std::abs(p[a] - plane) < 1e-5 && std::abs(q[a] - plane) < 1e-5;
    bad += !on_same_face;
  }
  return bad;
}

double trilinear_at(const std::vector<float>& v, const Index3& n, double x, double y, double z) {
  const int i = std::min(int(std::floor(x)), n[0] - 2), j = std::min(int(std::floor(y)), n[1] - 2),
            k = std::min(int(std::floor(z)), n[2] - 2);
  const double u = x - i, w1 = y - j, w2 = z - k;
  double f = 0;
  for (int c = 0; c < 8; ++c) {
    const int di = c & 1, dj = (c >> 1) & 1, dk = c >> 2;
    const double wgt = (di ? u : 1 - u) * (dj ? w1 : 1 - w1) * (dk ? w2 : 1 - w2);
    f += wgt * v[(size_t(k + dk) * n[1] + (j + dj)) * n[0] + (i + di)];
  }
  return f;
}

}  // namespace isoform::test
