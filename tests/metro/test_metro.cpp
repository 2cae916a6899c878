// The benchmark's Metro-style distance against distances known in closed
// form: each Voronoi region of a triangle, the tree against trying every
// triangle, two parallel planes, a square against a rectangle twice its
// size (one side zero, the other side's RMS from the integral), area-uniform
// sampling, and a coarse icosphere against a fine one.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "metro.h"

namespace irb = isoform_reduce_bench;

namespace {

struct TestMesh {
  std::vector<double> points;
  std::vector<int32_t> triangles;
  irb::MeshView view() const { return {points.data(), points.size() / 3, triangles.data(), triangles.size() / 3}; }
};

// n x n knots on [x0, x1] x [0, 1] at height z, the seed's split of each quad.
TestMesh grid(int n, double x0, double x1, double z) {
  TestMesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) m.points.insert(m.points.end(), {x0 + (x1 - x0) * i / (n - 1), double(j) / (n - 1), z});
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int32_t a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
    }
  return m;
}

// The icosahedron on the unit sphere, each triangle split in four `levels`
// times with the new points pushed onto the sphere.
TestMesh icosphere(int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  TestMesh m;
  m.points = {-1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, 0, 0, -1, t, 0, 1, t,
              0, -1, -t, 0, 1, -t, t, 0, -1, t, 0, 1, -t, 0, -1, -t, 0, 1};
  m.triangles = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
                 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  const auto push = [&](size_t v) {
    double* p = &m.points[3 * v];
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (int k = 0; k < 3; ++k) p[k] /= r;
  };
  for (size_t v = 0; v < 12; ++v) push(v);
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int32_t, int32_t>, int32_t> middles;
    const auto middle = [&](int32_t a, int32_t b) {
      const auto key = std::minmax(a, b);
      const auto found = middles.find(key);
      if (found != middles.end()) return found->second;
      const int32_t v = int32_t(m.points.size() / 3);
      for (int k = 0; k < 3; ++k) m.points.push_back(0.5 * (m.points[3 * a + k] + m.points[3 * b + k]));
      push(size_t(v));
      middles[key] = v;
      return v;
    };
    std::vector<int32_t> next;
    for (size_t f = 0; f < m.triangles.size(); f += 3) {
      const int32_t a = m.triangles[f], b = m.triangles[f + 1], c = m.triangles[f + 2];
      const int32_t ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    m.triangles.swap(next);
  }
  return m;
}

// How far the mesh's farthest point from the unit sphere lies inside it: 1
// minus the smallest distance from the centre to a triangle's plane (each
// triangle's foot point lies inside it on an icosphere).
double icosphere_deviation(const TestMesh& m) {
  double nearest = 1;
  for (size_t f = 0; f < m.triangles.size(); f += 3) {
    const double* a = &m.points[3 * size_t(m.triangles[f])];
    const double* b = &m.points[3 * size_t(m.triangles[f + 1])];
    const double* c = &m.points[3 * size_t(m.triangles[f + 2])];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    nearest = std::min(nearest, std::abs(n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) /
                                    std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
  }
  return 1 - nearest;
}

irb::TwoSidedError error_between(const TestMesh& a, const TestMesh& b, size_t samples) {
  const irb::TriangleTree ta(a.view()), tb(b.view());
  return irb::two_sided_error(irb::sample_surface(a.view(), samples, 1), ta, irb::sample_surface(b.view(), samples, 2), tb);
}

}  // namespace

TEST(PointTriangle, EachRegionOfTheUnitRightTriangle) {
  const irb::Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  EXPECT_DOUBLE_EQ(irb::point_triangle_distance2({0.2, 0.2, 3}, a, b, c), 9);     // face
  EXPECT_DOUBLE_EQ(irb::point_triangle_distance2({-1, -1, 0}, a, b, c), 2);       // corner a
  EXPECT_DOUBLE_EQ(irb::point_triangle_distance2({2, -1, 0}, a, b, c), 2);        // corner b
  EXPECT_DOUBLE_EQ(irb::point_triangle_distance2({-1, 3, 1}, a, b, c), 1 + 4 + 1);  // corner c
  EXPECT_DOUBLE_EQ(irb::point_triangle_distance2({0.5, -2, 1}, a, b, c), 5);      // edge ab
  EXPECT_DOUBLE_EQ(irb::point_triangle_distance2({-3, 0.5, 0}, a, b, c), 9);      // edge ca
  EXPECT_DOUBLE_EQ(irb::point_triangle_distance2({1, 1, 0}, a, b, c), 0.5);       // edge bc
  EXPECT_DOUBLE_EQ(irb::point_triangle_distance2({0.25, 0.25, 0}, a, b, c), 0);   // on it
}

TEST(PointTriangle, DegenerateTrianglesAreSegmentsOrPoints) {
  EXPECT_DOUBLE_EQ(irb::point_triangle_distance2({1, 1, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}), 1);
  EXPECT_DOUBLE_EQ(irb::point_triangle_distance2({3, 1, 0}, {0, 0, 0}, {2, 0, 0}, {2, 0, 0}), 2);
  EXPECT_DOUBLE_EQ(irb::point_triangle_distance2({1, 2, 5}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}), 4);
}

TEST(TriangleTree, SameAnswerAsTryingEveryTriangle) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0, 1), small(-0.1, 0.1), wide(-0.5, 1.5);
  TestMesh soup;
  for (int32_t t = 0; t < 700; ++t) {
    const double c[3] = {unit(rng), unit(rng), unit(rng)};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) soup.points.push_back(c[k] + small(rng));
    soup.triangles.insert(soup.triangles.end(), {3 * t, 3 * t + 1, 3 * t + 2});
  }
  const irb::TriangleTree tree(soup.view());
  EXPECT_EQ(tree.triangle_count(), 700u);
  for (int q = 0; q < 3000; ++q) {
    const irb::Vec3 p{wide(rng), wide(rng), wide(rng)};
    double brute = INFINITY;
    for (size_t t = 0; t < 700; ++t) {
      const double* v = &soup.points[9 * t];
      brute = std::min(brute, irb::point_triangle_distance2(p, {v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}));
    }
    ASSERT_EQ(tree.distance2(p), brute) << "query " << q;
    int32_t nearest = -1;
    ASSERT_EQ(tree.distance2(p, &nearest), brute);
    ASSERT_GE(nearest, 0);
    const double* v = &soup.points[9 * size_t(nearest)];
    ASSERT_EQ(irb::point_triangle_distance2(p, {v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}), brute)
        << "the triangle reported is not at the distance";
  }
}

TEST(TriangleTree, EmptyMeshIsInfinitelyFar) {
  const TestMesh empty;
  int32_t nearest = 7;
  EXPECT_TRUE(std::isinf(irb::TriangleTree(empty.view()).distance2({0, 0, 0}, &nearest)));
  EXPECT_EQ(nearest, -1);
}

TEST(Sampling, UniformByArea) {
  // Two triangles of areas 0.5 and 1.5 (a 1:3 split): a quarter of the samples in the first.
  TestMesh m;
  m.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 10, 0, 0, 13, 0, 0, 10, 1, 0};
  m.triangles = {0, 1, 2, 3, 4, 5};
  const irb::SurfaceSamples s = irb::sample_surface(m.view(), 100000, 3);
  ASSERT_EQ(s.area_samples, 100000u);
  EXPECT_EQ(s.count(), 100006u);  // and the six vertices
  EXPECT_DOUBLE_EQ(s.area, 2.0);
  size_t first = 0;
  for (size_t k = 0; k < s.area_samples; ++k) {
    const double x = s.points[3 * k], y = s.points[3 * k + 1];
    first += x < 5;
    ASSERT_GE(y, 0);
    ASSERT_LE(x < 5 ? x + y : (x - 10) / 3 + y, 1 + 1e-12) << "sample outside its triangle";
  }
  EXPECT_NEAR(double(first) / 100000, 0.25, 0.005);
}

TEST(TwoSided, ParallelPlanesAtDistanceD) {
  const double d = 0.25;
  const irb::TwoSidedError e = error_between(grid(11, 0, 1, 0), grid(7, 0, 1, d), 20000);
  EXPECT_NEAR(e.a_to_b.max, d, 1e-12);
  EXPECT_NEAR(e.b_to_a.max, d, 1e-12);
  EXPECT_NEAR(e.a_to_b.rms, d, 1e-12);
  EXPECT_NEAR(e.b_to_a.mean, d, 1e-12);
  EXPECT_NEAR(e.max(), d, 1e-12);
  EXPECT_NEAR(e.rms(), d, 1e-12);
}

TEST(TwoSided, SquareAgainstRectangleTwiceItsSize) {
  // A = [0,1]^2 lies in B = [0,2]x[0,1]: A to B is 0. From B, the half x > 1
  // is x - 1 from A: the maximum 1 at B's far corners, RMS^2 = 1/2 * 1/3.
  const irb::TwoSidedError e = error_between(grid(5, 0, 1, 0), grid(9, 0, 2, 0), 200000);
  EXPECT_LT(e.a_to_b.max, 1e-15);
  EXPECT_DOUBLE_EQ(e.b_to_a.max, 1.0);
  EXPECT_NEAR(e.b_to_a.rms, std::sqrt(1.0 / 6), 0.004);
  EXPECT_NEAR(e.b_to_a.mean, 0.25, 0.004);  // 1/2 * 1/2
  EXPECT_DOUBLE_EQ(e.max(), 1.0);
}

TEST(TwoSided, CoarseIcosphereAgainstAFineOne) {
  // The fine mesh is within fine_dev of the sphere, so the distance between
  // the two is the coarse mesh's own deviation up to fine_dev.
  const TestMesh coarse = icosphere(1), fine = icosphere(5);
  const double coarse_dev = icosphere_deviation(coarse), fine_dev = icosphere_deviation(fine);
  ASSERT_GT(coarse_dev, 0.05);  // 80 triangles: 0.066 inside at the face centres
  ASSERT_LT(fine_dev, 0.001);
  const irb::TwoSidedError e = error_between(coarse, fine, 100000);
  EXPECT_NEAR(e.max(), coarse_dev, fine_dev + 1e-4);
  EXPECT_GT(e.rms(), 0.3 * coarse_dev);
  EXPECT_LT(e.rms(), e.max());
  // The first split puts points at (+-1, 0, 0) and its cyclic shifts (the middle of
  // (t, 0, -1) and (t, 0, 1) pushed out), so the bounding box is [-1, 1]^3.
  EXPECT_NEAR(irb::bbox_diagonal(coarse.view()), 2 * std::sqrt(3.0), 1e-12);
}
