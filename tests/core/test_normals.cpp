// Normals: the Zucker-Hummel operator (Theorem 3.8) and the mesh-only
// estimate of Remark 3.15.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "libcore/contour/gradient.h"
#include "libcore/mesh_normals.h"
#include "mesh_checks.h"

using namespace isoform;

TEST(ZuckerHummel, ExactOnLinearFunctions) {
  Brick b;
  b.resize({0, 0, 0}, {2, 2, 2}, false);
  for (int k = -1; k <= 3; ++k)
    for (int j = -1; j <= 3; ++j)
      for (int i = -1; i <= 3; ++i) b.samples[b.at(i, j, k)] = float(0.5 * i - 2.0 * j + 3.0 * k + 1);
  const Vec3d g = zucker_hummel(b, 1, 1, 1);
  EXPECT_NEAR(g[0], 0.5, 1e-6);
  EXPECT_NEAR(g[1], -2.0, 1e-6);
  EXPECT_NEAR(g[2], 3.0, 1e-6);
}

// Four samples of a row at a time give the one-at-a-time sums to the bit
// (the contour's normals depend on it), on random data with every scale.
TEST(ZuckerHummel, FourAtATimeSameBitsAsOne) {
  if (!has_zucker_hummel_four()) GTEST_SKIP() << "no AVX on this processor";
  Brick b;
  b.resize({0, 0, 0}, {8, 8, 8}, false);
  uint32_t state = 12345;
  for (float& f : b.samples) {
    state = state * 1664525u + 1013904223u;
    f = float(int32_t(state >> 8) - (1 << 23)) * std::ldexp(1.0f, int(state % 40) - 30);
  }
  const Index3 d = b.dims();
  const size_t row = size_t(d[0]), slice = size_t(d[0]) * size_t(d[1]);
  int compared = 0;
  for (int k = 0; k <= 8; ++k)
    for (int j = 0; j <= 8; ++j)
      for (int i = 0; i + 3 <= 8; ++i) {
        Vec3d four[4];
        zucker_hummel_four(&b.samples[b.at(i, j, k)], row, slice, four);
        for (int l = 0; l < 4; ++l) {
          const Vec3d one = zucker_hummel_inside(&b.samples[b.at(i + l, j, k)], row, slice);
          for (int a = 0; a < 3; ++a) {
            ASSERT_EQ(std::memcmp(&four[l][a], &one[a], sizeof(double)), 0) << i + l << " " << j << " " << k;
            ++compared;
          }
        }
      }
  EXPECT_EQ(compared, 9 * 9 * 6 * 4 * 3);
}

TEST(ZuckerHummel, ExtrapolatesAtTheEdgeOfADenseArray) {
  Brick b;
  b.resize({0, 0, 0}, {2, 2, 2}, true);
  for (int k = -1; k <= 3; ++k)
    for (int j = -1; j <= 3; ++j)
      for (int i = -1; i <= 3; ++i) {
        const bool inside = i >= 0 && j >= 0 && k >= 0 && i <= 2 && j <= 2 && k <= 2;
        b.samples[b.at(i, j, k)] = inside ? float(2.0 * i + j - k) : 1e6f;
        b.defined[b.at(i, j, k)] = inside;
      }
  const Vec3d g = zucker_hummel(b, 0, 0, 0);
  EXPECT_NEAR(g[0], 2.0, 1e-5);
  EXPECT_NEAR(g[1], 1.0, 1e-5);
  EXPECT_NEAR(g[2], -1.0, 1e-5);
}

TEST(MeshNormals, OneRingFitOnASphereContour) {
  // A contour's own normals compared with those estimated from its triangles.
  const Index3 n{40, 40, 40};
  auto g = test::dense_grid(n, [](int x, int y, int z) { return std::hypot(x - 19.5, y - 19.2, z - 19.7) - 14.3; },
                            GridClass::LevelSet);
  Mesh m = test::run_contour(*g, 0.0);
  double worst = 1.0;
  Mesh estimated = m;
  estimate_normals(estimated);
  for (size_t p = 0; p < m.vertex_count(); ++p) {
    const double r[3] = {m.points[3 * p] - 19.5, m.points[3 * p + 1] - 19.2, m.points[3 * p + 2] - 19.7};
    const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    double dot = 0;
    for (int a = 0; a < 3; ++a) dot += r[a] / len * estimated.normals[3 * p + a];
    worst = std::min(worst, dot);
  }
  EXPECT_GT(worst, 0.97);  // within about 14 degrees everywhere, outward
}

TEST(MeshNormals, SingularRingFallsBackToTheQr) {
  // A vertex at the origin whose eight neighbours lie on the x and y axes,
  // on the graph z = 0.3 x^2 - 0.2 y^2: in its first frame (axes x and y,
  // height z) every neighbour has x y = 0, so the quadratic's normal
  // equations are singular and the column-pivoting QR solves the fit. The
  // graph's normal at the origin is (0, 0, 1); the second fit, in the frame
  // the first one found, must keep it.
  Mesh m;
  const double ring[8][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {2, 0}, {0, 2}, {-2, 0}, {0, -2}};
  m.points = {0, 0, 0};
  for (const auto& p : ring) {
    m.points.push_back(float(p[0]));
    m.points.push_back(float(p[1]));
    m.points.push_back(float(0.3 * p[0] * p[0] - 0.2 * p[1] * p[1]));
  }
  // Two fans around the origin, counter-clockwise seen from +z: the inner
  // square of neighbours and the outer one.
  for (int i = 0; i < 4; ++i) {
    m.triangles.insert(m.triangles.end(), {0, 1 + i, 1 + (i + 1) % 4});
    m.triangles.insert(m.triangles.end(), {0, 5 + i, 5 + (i + 1) % 4});
  }
  estimate_normals(m);
  ASSERT_EQ(m.normals.size(), m.points.size());
  const float* n = &m.normals[0];
  for (int a = 0; a < 3; ++a) ASSERT_TRUE(std::isfinite(n[a]));
  EXPECT_NEAR(n[0], 0.0, 1e-6);
  EXPECT_NEAR(n[1], 0.0, 1e-6);
  EXPECT_NEAR(n[2], 1.0, 1e-6);
}

namespace {

// Remark 3.15's estimate as estimate_normals states it, every fit solved by
// a column-pivoting QR: the reference for the normal-equations path.
Eigen::Vector3d reference_normal(const Mesh& m, int32_t v) {
  auto point = [&](int32_t i) {
    return Eigen::Vector3d(m.points[3 * size_t(i)], m.points[3 * size_t(i) + 1], m.points[3 * size_t(i) + 2]);
  };
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  std::vector<int32_t> ring;
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const int32_t* tri = &m.triangles[3 * t];
    for (int i = 0; i < 3; ++i)
      if (tri[i] == v) {
        n += (point(tri[1]) - point(tri[0])).cross(point(tri[2]) - point(tri[0]));
        ring.push_back(tri[(i + 1) % 3]);
        ring.push_back(tri[(i + 2) % 3]);
      }
  }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  if (n.norm() == 0 || ring.size() < 2) return {0, 0, 1};
  n.normalize();
  for (int pass = 0; pass < 2; ++pass) {
    const Eigen::Vector3d d1 = n.unitOrthogonal(), d2 = n.cross(d1);
    const bool quadratic = ring.size() >= 7;
    Eigen::MatrixXd a(Eigen::Index(ring.size()), quadratic ? 5 : 2);
    Eigen::VectorXd h(Eigen::Index(ring.size()));
    for (size_t j = 0; j < ring.size(); ++j) {
      const Eigen::Vector3d p = point(ring[j]) - point(v);
      const double x = p.dot(d1), y = p.dot(d2);
      a(Eigen::Index(j), 0) = x;
      a(Eigen::Index(j), 1) = y;
      if (quadratic) {
        a(Eigen::Index(j), 2) = x * x;
        a(Eigen::Index(j), 3) = x * y;
        a(Eigen::Index(j), 4) = y * y;
      }
      h(Eigen::Index(j)) = p.dot(n);
    }
    const Eigen::VectorXd c = a.colPivHouseholderQr().solve(h);
    if (!c.allFinite()) continue;
    const Eigen::Vector3d next = (n - c(0) * d1 - c(1) * d2).normalized();
    if (next.allFinite() && next.dot(n) > 0) n = next;
  }
  return n;
}

}  // namespace

TEST(MeshNormals, NormalEquationsGiveTheQrsNormals) {
  // A contour of an ellipsoid (valences 3 to 9 or so: plane and quadratic
  // fits both) with every point jittered: each estimated normal against
  // the reference's, to float rounding. A scale left out of a coefficient,
  // or a lost term, moves normals by 1e-3 or more.
  const Index3 n{36, 36, 36};
  auto g = test::dense_grid(
      n, [](int x, int y, int z) { return std::hypot((x - 17.5) / 1.3, y - 17.2, (z - 17.7) / 0.8) - 11.3; },
      GridClass::LevelSet);
  Mesh m = test::run_contour(*g, 0.0);
  uint32_t state = 12345;
  for (float& c : m.points) {
    state = state * 1664525u + 1013904223u;
    c += 0.15f * (float(state >> 8) / float(1 << 24) - 0.5f);
  }
  Mesh estimated = m;
  estimate_normals(estimated);
  double worst = 0;
  size_t quadratic = 0;
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    const Eigen::Vector3d r = reference_normal(m, int32_t(v));
    for (int a = 0; a < 3; ++a) worst = std::max(worst, std::abs(estimated.normals[3 * v + size_t(a)] - r[a]));
  }
  // A closed manifold vertex has as many neighbours as triangles.
  std::vector<int> valence(m.vertex_count(), 0);
  for (int32_t c : m.triangles) ++valence[size_t(c)];
  for (int d : valence) quadratic += d >= 7;
  EXPECT_GT(quadratic, m.vertex_count() / 10);
  EXPECT_LT(quadratic, m.vertex_count());
  EXPECT_LT(worst, 1e-6);
}
