#include "patch_fixtures.h"

#include <cmath>

#include "libcore/topology.h"

namespace isoform::patch::test {
namespace {

Mesh from(const std::vector<double>& p, const std::vector<double>& n, const std::vector<int32_t>& t) {
  Mesh m;
  m.precise_points = p;
  m.points.assign(p.begin(), p.end());
  m.normals.assign(n.begin(), n.end());
  m.triangles = t;
  compute_topology(m);
  return m;
}

std::vector<double> normalised(std::vector<double> p) {
  for (size_t i = 0; i < p.size(); i += 3) {
    const double l = std::sqrt(p[i] * p[i] + p[i + 1] * p[i + 1] + p[i + 2] * p[i + 2]);
    for (int a = 0; a < 3; ++a) p[i + a] /= l;
  }
  return p;
}

}  // namespace

Mesh tetrahedron() {
  const std::vector<double> p = normalised({1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1});
  return from(p, p, {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2});
}

Mesh icosahedron() {
  const double g = (1 + std::sqrt(5.0)) / 2;
  const std::vector<double> p = normalised({-1, g, 0, 1, g, 0, -1, -g, 0, 1, -g, 0, 0, -1, g, 0, 1, g,
                                            0, -1, -g, 0, 1, -g, g, 0, -1, g, 0, 1, -g, 0, -1, -g, 0, 1});
  return from(p, p, {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2,
                     10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5,
                     2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1});
}

Mesh skewed_octahedron() {
  const double s[3] = {1.0, 0.7, 1.3};
  std::vector<double> p = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  std::vector<double> n(p.size());
  for (size_t i = 0; i < p.size(); i += 3) {
    for (int a = 0; a < 3; ++a) {
      p[i + a] *= s[a];
      n[i + a] = p[i + a] / (s[a] * s[a]);
    }
    // A small turn that differs per vertex (about 0.2 rad), fixed.
    const double k = 0.2 * std::sin(double(i) * 1.7 + 0.3);
    const double x = n[i], y = n[i + 1];
    n[i] = std::cos(k) * x - std::sin(k) * y + 0.1 * k;
    n[i + 1] = std::sin(k) * x + std::cos(k) * y;
  }
  return from(p, normalised(n), {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5});
}

}  // namespace isoform::patch::test
