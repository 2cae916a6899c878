// Contours of analytic and random fields (Sections 3.2 to 3.4): closed or
// bounded only by the domain, manifold, oriented, on the trilinear contour,
// with the topology the geometry implies.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "libcore/topology.h"
#include "mesh_checks.h"

using namespace isoform;
using namespace isoform::test;

namespace {

void expect_clean(const Mesh& m, const Index3& n) {
  EXPECT_GT(m.triangle_count(), 0u);
  EXPECT_EQ(m.stats.nonmanifold_edges, 0);
  EXPECT_EQ(m.stats.inconsistent_edges, 0);
  EXPECT_EQ(interior_boundary_edges(m, n), 0);
}

double torus(double x, double y, double z, double R, double r) {
  const double q = std::sqrt(x * x + y * y) - R;
  return std::sqrt(q * q + z * z) - r;
}

}  // namespace

TEST(Contour, Figure36HyperboloidMeetsTheDomainOnlyOnItsFaces) {
  const Index3 n{21, 21, 21};
  auto g = dense_grid(n, [](int x, int y, int z) {
    return 1.2 * ((x - 10.0) * (x - 10.0) - (y - 10.0) * (y - 10.0) + (z - 10.0) * (z - 10.0));
  });
  for (ContourMethod method : {ContourMethod::Cells, ContourMethod::Tetra}) {
    const Mesh m = run_contour(*g, 60.0, method);
    expect_clean(m, n);
    EXPECT_GT(m.stats.boundary_edges, 0);  // it leaves the box through its faces
    // One sheet around the y axis, cut by the box: one connected part.
    EXPECT_EQ(m.part_count, 1);
  }
}

TEST(Contour, RandomFieldsAreManifoldAndOnTheTrilinearContour) {
  const Index3 n{32, 32, 32};
  for (unsigned seed = 1; seed <= 24; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<float> v(size_t(n[0]) * n[1] * n[2]);
    for (float& x : v) x = u(rng);
    auto g = dense_grid(n, v);
    for (ContourMethod method : {ContourMethod::Cells, ContourMethod::Tetra}) {
      const Mesh m = run_contour(*g, 0.1, method);
      SCOPED_TRACE("seed " + std::to_string(seed) + (method == ContourMethod::Cells ? " cells" : " tetra"));
      expect_clean(m, n);
      EXPECT_EQ(m.stats.degenerate_triangles, 0);
      if (method != ContourMethod::Cells) continue;
      // Every vertex but the centroid fallbacks and the crossings held off a
      // sample lies on f = iso; those lie within 1/1000 of an edge of it.
      long long off = 0;
      for (size_t p = 0; p < m.vertex_count(); ++p) {
        const double f = trilinear_at(v, n, m.points[3 * p], m.points[3 * p + 1], m.points[3 * p + 2]);
        off += std::abs(f - 0.1) > 1e-5;
      }
      EXPECT_LE(off, m.contour.centroid_points + m.contour.near_sample_points);
      EXPECT_LT(m.contour.near_sample_points, (long long)m.vertex_count() / 200);
      EXPECT_GT(m.contour.extra_points, 0);
    }
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(Contour, SphereTorusGenusTwoAndTwoSpheres) {
  const Index3 n{48, 48, 48};
  struct Shape {
    const char* name;
    std::function<double(int, int, int)> f;
    long long euler;
    int parts;
  };
  const std::vector<Shape> shapes = {
      {"sphere", [](int x, int y, int z) { return std::hypot(x - 23.5, y - 23.2, z - 23.7) - 15.3; }, 2, 1},
      {"torus", [](int x, int y, int z) { return torus(x - 23.5, y - 23.2, z - 23.7, 13.1, 5.3); }, 0, 1},
      {"genus 2",
       [](int x, int y, int z) {
         return std::min(torus(x - 14.5, y - 23.2, z - 23.7, 9.1, 3.9), torus(x - 32.1, y - 23.2, z - 23.7, 9.1, 3.9));
       },
       -2, 1},
      {"two spheres",
       [](int x, int y, int z) {
         return std::min(std::hypot(x - 12.5, y - 23.2, z - 23.7) - 8.3, std::hypot(x - 34.5, y - 23.2, z - 23.7) - 6.1);
       },
       4, 2},
  };
  for (const Shape& s : shapes)
    for (ContourMethod method : {ContourMethod::Cells, ContourMethod::Tetra}) {
      SCOPED_TRACE(s.name);
      auto g = dense_grid(n, s.f, GridClass::LevelSet);
      const Mesh m = run_contour(*g, 0.0, method);
      expect_clean(m, n);
      EXPECT_EQ(m.stats.boundary_edges, 0);
      EXPECT_EQ(m.stats.euler_characteristic, s.euler);
      EXPECT_EQ(m.part_count, s.parts);
    }
}

TEST(Contour, LevelSetNormalsAndTrianglesFaceOutward) {
  const Index3 n{32, 32, 32};
  auto g = dense_grid(n, [](int x, int y, int z) { return std::hypot(x - 15.5, y - 15.2, z - 15.7) - 10.3; },
                      GridClass::LevelSet);
  const Mesh m = run_contour(*g, 0.0);
  for (size_t p = 0; p < m.vertex_count(); ++p) {
    const double r[3] = {m.points[3 * p] - 15.5, m.points[3 * p + 1] - 15.2, m.points[3 * p + 2] - 15.7};
    const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    const double dot = (r[0] * m.normals[3 * p] + r[1] * m.normals[3 * p + 1] + r[2] * m.normals[3 * p + 2]) / len;
    ASSERT_GT(dot, 0.99) << "vertex " << p;  // Zucker-Hummel on a sphere of radius 10
  }
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    const float* a = &m.points[3 * size_t(m.triangles[3 * t])];
    const float* b = &m.points[3 * size_t(m.triangles[3 * t + 1])];
    const float* c = &m.points[3 * size_t(m.triangles[3 * t + 2])];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double nrm[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double out = nrm[0] * (a[0] - 15.5) + nrm[1] * (a[1] - 15.2) + nrm[2] * (a[2] - 15.7);
    ASSERT_GT(out, 0) << "triangle " << t;
  }
  // A fog-class grid of the same values faces the other way by default.
  auto fog = dense_grid(n, [](int x, int y, int z) { return std::hypot(x - 15.5, y - 15.2, z - 15.7) - 10.3; });
  const Mesh f = run_contour(*fog, 0.0);
  ASSERT_EQ(f.vertex_count(), m.vertex_count());
  EXPECT_LT(f.normals[0] * m.normals[0] + f.normals[1] * m.normals[1] + f.normals[2] * m.normals[2], -0.99);
}

TEST(Contour, TiesFromTheSeedExampleAndIntegerIsovalues) {
  // The 2x2x3 field (x fastest) padded with its minimum so the surface closes.
  const float core[3][2][2] = {{{13, -1}, {-1, -7}}, {{-1, 1}, {7, -7}}, {{15, -9}, {-3, -1}}};
  const Index3 n{4, 4, 5};
  std::vector<float> v(size_t(n[0]) * n[1] * n[2], -9.0f);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) v[(size_t(k + 1) * n[1] + (j + 1)) * n[0] + (i + 1)] = core[k][j][i];
  auto g = dense_grid(n, v);
  for (double iso : {0.0, -1.0, 1.0, 7.0, -7.0, -3.0})
    for (ContourMethod method : {ContourMethod::Cells, ContourMethod::Tetra}) {
      SCOPED_TRACE("iso " + std::to_string(iso));
      const Mesh m = run_contour(*g, iso, method);
      expect_clean(m, n);
      EXPECT_EQ(m.stats.boundary_edges, 0);
      EXPECT_EQ(m.stats.degenerate_triangles, 0);
    }
}

TEST(Contour, RandomIntegerFieldsAtIntegerIsovalues) {
  const Index3 n{24, 24, 24};
  for (unsigned seed = 1; seed <= 8; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> u(0, 4);
    std::vector<float> v(size_t(n[0]) * n[1] * n[2]);
    for (float& x : v) x = float(u(rng));
    auto g = dense_grid(n, v);
    for (double iso : {1.0, 2.0, 2.5}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " iso " + std::to_string(iso));
      const Mesh m = run_contour(*g, iso);
      expect_clean(m, n);
      EXPECT_EQ(m.stats.degenerate_triangles, 0);
      if (iso == 2.5) {
        EXPECT_GT(m.contour.degenerate_saddles, 0);
      }
    }
  }
}

TEST(Contour, SerialAndParallelRunsGiveTheSameMesh) {
  const Index3 n{40, 37, 45};
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<float> v(size_t(n[0]) * n[1] * n[2]);
  for (float& x : v) x = u(rng);
  auto g = dense_grid(n, v);
  const Mesh a = run_contour(*g, 0.0, ContourMethod::Cells, 1);
  const Mesh b = run_contour(*g, 0.0, ContourMethod::Cells, 2);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.neighbours, b.neighbours);
  EXPECT_EQ(a.parts, b.parts);
}

TEST(Contour, BrickTopologyEqualsTheWholeMeshAlgorithm) {
  // Random fields make many parts and many edges on brick faces; the
  // contour's neighbours, parts and counts (found brick by brick, then
  // across brick faces) must be those of compute_topology on its output,
  // for both methods and both orientations.
  const Index3 n{37, 41, 35};
  for (unsigned seed = 1; seed <= 6; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<float> v(size_t(n[0]) * n[1] * n[2]);
    for (float& x : v) x = u(rng);
    auto g = dense_grid(n, v, seed % 2 ? GridClass::LevelSet : GridClass::Other);
    for (ContourMethod method : {ContourMethod::Cells, ContourMethod::Tetra}) {
      SCOPED_TRACE("seed " + std::to_string(seed));
      const Mesh m = run_contour(*g, 0.2, method, 2);
      Mesh again;
      again.points = m.points;
      again.triangles = m.triangles;
      compute_topology(again);
      EXPECT_GT(m.part_count, 10);
      // Fans from extra points (their spokes are linked inside the fan) occur,
      // faces with two sides, and sides whose cell across was not contoured
      // (the array ends inside a brick: boundary edges).
      if (method == ContourMethod::Cells) {
        EXPECT_GT(m.contour.extra_points + m.contour.centroid_points, 0);
        EXPECT_GT(m.contour.ambiguous_faces, 0);
      }
      EXPECT_GT(m.stats.boundary_edges, 0);
      EXPECT_EQ(m.neighbours, again.neighbours);
      EXPECT_EQ(m.parts, again.parts);
      EXPECT_EQ(m.part_count, again.part_count);
      EXPECT_EQ(m.stats.boundary_edges, again.stats.boundary_edges);
      EXPECT_EQ(m.stats.nonmanifold_edges, again.stats.nonmanifold_edges);
      EXPECT_EQ(m.stats.inconsistent_edges, again.stats.inconsistent_edges);
      EXPECT_EQ(m.stats.degenerate_triangles, again.stats.degenerate_triangles);
      EXPECT_EQ(m.stats.euler_characteristic, again.stats.euler_characteristic);
    }
  }
}

TEST(Contour, IsovalueOutsideTheRangeGivesAnEmptyMesh) {
  auto g = dense_grid({8, 8, 8}, [](int x, int, int) { return double(x); });
  const Mesh m = run_contour(*g, 100.0);
  EXPECT_EQ(m.triangle_count(), 0u);
  EXPECT_EQ(m.part_count, 0);
}
