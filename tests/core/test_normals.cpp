// Normals: the Zucker-Hummel operator (Theorem 3.8) and the mesh-only
// estimate of Remark 3.15.
#include <gtest/gtest.h>

#include <cmath>

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
