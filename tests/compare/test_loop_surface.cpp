// The Loop limit surface (OpenSubdiv) against what is known by hand: the
// limit-point formula at vertices, the corners of each face's (u, v),
// derivatives against differences, C1 continuity across edges of regular
// patches, and that it does not pass through the data points.
#include <cmath>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "compare_meshes.h"
#include "libcore/compare/loop_surface.h"

namespace isoform::test {
namespace {

using compare::LoopOptions;
using compare::make_loop_surface;
using V3 = std::array<double, 3>;

const double kPi = 3.14159265358979323846;

std::unique_ptr<TriangleSurface> loop(const Mesh& mesh, int isolation = 6) {
  std::string error;
  LoopOptions o;
  o.isolation = isolation;
  auto s = make_loop_surface(mesh, o, error);
  EXPECT_TRUE(s) << error;
  return s;
}

double distance(const V3& a, const V3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// Loop's limit point of an interior vertex of valence n: (1 - n chi) v +
// chi * (sum of its neighbours), chi = 1 / (n + 3 / (8 beta)), with Loop's
// beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n. For n = 6: 1/2 and 1/12.
V3 limit_point(const Mesh& mesh, int v) {
  std::set<int> ring;
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i)
      if (mesh.triangles[3 * t + size_t(i)] == v) {
        ring.insert(mesh.triangles[3 * t + size_t((i + 1) % 3)]);
        ring.insert(mesh.triangles[3 * t + size_t((i + 2) % 3)]);
      }
  const double n = double(ring.size());
  const double c = 3.0 / 8.0 + std::cos(2 * kPi / n) / 4.0;
  const double beta = (5.0 / 8.0 - c * c) / n;
  const double chi = 1.0 / (n + 3.0 / (8.0 * beta));
  V3 out = vertex(mesh, v);
  for (int k = 0; k < 3; ++k) out[k] *= 1.0 - n * chi;
  for (int w : ring) {
    const V3 q = vertex(mesh, w);
    for (int k = 0; k < 3; ++k) out[k] += chi * q[k];
  }
  return out;
}

// Every corner (0,0), (1,0), (0,1) of every face is the limit point of
// vertex t0, t1, t2 respectively.
void expect_corners_are_limit_points(const Mesh& mesh, double tolerance) {
  auto s = loop(mesh);
  ASSERT_TRUE(s);
  const double corners[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  for (size_t t = 0; t < mesh.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) {
      SurfaceSample x;
      ASSERT_TRUE(s->evaluate(t, corners[i][0], corners[i][1], x));
      const V3 want = limit_point(mesh, mesh.triangles[3 * t + size_t(i)]);
      EXPECT_LT(distance(x.point, want), tolerance) << "triangle " << t << " corner " << i;
    }
}

TEST(LoopSurface, CornersAreLimitPointsOfValence4) { expect_corners_are_limit_points(octahedron(), 1e-12); }
TEST(LoopSurface, CornersAreLimitPointsOfValence5) { expect_corners_are_limit_points(icosahedron(0.05), 1e-12); }
TEST(LoopSurface, CornersAreLimitPointsOfValence6) {
  expect_corners_are_limit_points(regular_torus(12, 8, 2.0, 0.7), 1e-12);
}

TEST(LoopSurface, ValenceSixWeightsAreOneHalfAndOneTwelfth) {
  // The formula above, checked against the weights every text on Loop gives.
  const Mesh m = regular_torus(12, 8, 2.0, 0.7);
  const V3 got = limit_point(m, 0);
  // Neighbours of (0,0) in the split used: (1,0), (1,1), (0,1), (-1,0), (-1,-1), (0,-1).
  const int ring[6] = {1 * 8 + 0, 1 * 8 + 1, 0 * 8 + 1, 11 * 8 + 0, 11 * 8 + 7, 0 * 8 + 7};
  V3 want = vertex(m, 0);
  for (int k = 0; k < 3; ++k) want[k] *= 0.5;
  for (int w : ring)
    for (int k = 0; k < 3; ++k) want[k] += vertex(m, w)[k] / 12.0;
  EXPECT_LT(distance(got, want), 1e-14);
}

TEST(LoopSurface, DoesNotInterpolateTheDataPoints) {
  // On the octahedron the limit point of each vertex lies at 1 - 4 chi
  // (1 - 0) = 1 - 4 chi from the centre along its axis: inside the sphere.
  const Mesh m = octahedron();
  auto s = loop(m);
  ASSERT_TRUE(s);
  const double c = 3.0 / 8.0 + std::cos(kPi / 2) / 4.0, beta = (5.0 / 8.0 - c * c) / 4.0;
  const double chi = 1.0 / (4.0 + 3.0 / (8.0 * beta));
  SurfaceSample x;
  ASSERT_TRUE(s->evaluate(0, 0, 0, x));  // vertex 0 = (1, 0, 0)
  EXPECT_NEAR(x.point[0], 1.0 - 4.0 * chi, 1e-13);
  EXPECT_NEAR(x.point[1], 0.0, 1e-13);
  EXPECT_GT(distance(x.point, vertex(m, 0)), 0.3);  // chi = 1/(4 + 3/(8 beta)) ~ 0.091 -> 0.36
}

// du, dv, duu, duv, dvv against central differences of the position (and of
// du, dv), at points inside corner, edge and centre sub-triangles.
void expect_derivatives_match_differences(int isolation) {
  const Mesh m = icosahedron(0.05);
  auto s = loop(m, isolation);
  ASSERT_TRUE(s);
  const double h = 1e-5;
  // None on a boundary of the sub-triangles of levels 1 to 3 (multiples of
  // 1/8 in u, v or u + v), where patches meet only with G1 continuity.
  const double params[][2] = {{0.3, 0.3}, {1.0 / 3, 1.0 / 3}, {0.2, 0.45}, {0.05, 0.1}, {0.6, 0.2}, {0.43, 0.43},
                              {0.1, 0.7}, {0.7, 0.1}, {0.15, 0.2}};
  for (size_t t = 0; t < m.triangle_count(); t += 3)
    for (const auto& uv : params) {
      SurfaceSample x, pu, mu, pv, mv;
      ASSERT_TRUE(s->evaluate(t, uv[0], uv[1], x));
      ASSERT_TRUE(x.has_second);
      ASSERT_TRUE(s->evaluate(t, uv[0] + h, uv[1], pu) && s->evaluate(t, uv[0] - h, uv[1], mu));
      ASSERT_TRUE(s->evaluate(t, uv[0], uv[1] + h, pv) && s->evaluate(t, uv[0], uv[1] - h, mv));
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(x.du[k], (pu.point[k] - mu.point[k]) / (2 * h), 1e-6) << t << " at " << uv[0] << "," << uv[1];
        EXPECT_NEAR(x.dv[k], (pv.point[k] - mv.point[k]) / (2 * h), 1e-6) << t << " at " << uv[0] << "," << uv[1];
        EXPECT_NEAR(x.duu[k], (pu.du[k] - mu.du[k]) / (2 * h), 1e-4) << t << " at " << uv[0] << "," << uv[1];
        EXPECT_NEAR(x.duv[k], (pv.du[k] - mv.du[k]) / (2 * h), 1e-4) << t << " at " << uv[0] << "," << uv[1];
        EXPECT_NEAR(x.dvv[k], (pv.dv[k] - mv.dv[k]) / (2 * h), 1e-4) << t << " at " << uv[0] << "," << uv[1];
      }
    }
}

TEST(LoopSurface, DerivativesMatchDifferences) { expect_derivatives_match_differences(6); }

// Isolation 1 leaves Gregory end caps over the three corner quarters of each
// face. There OpenSubdiv's derivatives are approximate, so no second
// derivatives are offered; at the corner itself (a base vertex) the first
// derivatives are exact: they match one-sided differences of the position.
TEST(LoopSurface, DerivativesInGregoryEndCaps) {
  const Mesh m = icosahedron(0.05);
  auto s = loop(m, 1);
  ASSERT_TRUE(s);
  const double h = 1e-5;
  double worst_inside = 0.0;
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    SurfaceSample c, u1, u2, v1, v2, inside, centre;
    ASSERT_TRUE(s->evaluate(t, 0, 0, c) && s->evaluate(t, h, 0, u1) && s->evaluate(t, 2 * h, 0, u2));
    ASSERT_TRUE(s->evaluate(t, 0, h, v1) && s->evaluate(t, 0, 2 * h, v2));
    EXPECT_FALSE(c.has_second);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(c.du[k], (-3 * c.point[k] + 4 * u1.point[k] - u2.point[k]) / (2 * h), 1e-6) << t;
      EXPECT_NEAR(c.dv[k], (-3 * c.point[k] + 4 * v1.point[k] - v2.point[k]) / (2 * h), 1e-6) << t;
    }
    ASSERT_TRUE(s->evaluate(t, 0.15, 0.2, inside));
    EXPECT_FALSE(inside.has_second);
    SurfaceSample pu, mu;
    ASSERT_TRUE(s->evaluate(t, 0.15 + h, 0.2, pu) && s->evaluate(t, 0.15 - h, 0.2, mu));
    for (int k = 0; k < 3; ++k) worst_inside = std::max(worst_inside, std::abs(inside.du[k] - (pu.point[k] - mu.point[k]) / (2 * h)));
    ASSERT_TRUE(s->evaluate(t, 1.0 / 3, 1.0 / 3, centre));  // the regular centre sub-triangle
    EXPECT_TRUE(centre.has_second);
  }
  // The approximation inside the end caps, as measured (about 1e-2 here).
  RecordProperty("gregory_du_error", std::to_string(worst_inside));
  EXPECT_GT(worst_inside, 1e-6);
  EXPECT_LT(worst_inside, 0.1);
}

// The angle between unit vectors, accurate near 0 (acos is not: acos(1 - 1e-16) = 1.5e-8).
double angle(const V3& a, const V3& b) {
  const V3 c = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

// Largest angle between the normals of the two faces at points of their
// shared edges, over every edge of the mesh.
double largest_normal_gap(const Mesh& m, const TriangleSurface& s, int samples) {
  double worst = 0.0;
  for (size_t t = 0; t < m.triangle_count(); ++t)
    for (int e = 0; e < 3; ++e) {
      const int32_t o = m.neighbours[3 * t + size_t(e)];
      if (o < 0 || size_t(o) < t) continue;
      const int32_t a = m.triangles[3 * t + size_t(e)];
      int f = 0;
      while (m.triangles[3 * size_t(o) + size_t(f)] != a) ++f;
      // In o the edge runs from b (corner f + 2 ... ) to a: a is corner f, so
      // the edge is (corner f-1 = b) -> (corner f = a), fraction measured from b.
      const int g = (f + 2) % 3;  // o's edge g runs from b to a
      for (int j = 0; j < samples; ++j) {
        const double sfrac = (j + 0.5) / samples;  // from a toward b in t
        double w[3] = {0, 0, 0}, wo[3] = {0, 0, 0};
        w[e] = 1 - sfrac;
        w[(e + 1) % 3] = sfrac;
        wo[g] = sfrac;
        wo[(g + 1) % 3] = 1 - sfrac;
        SurfaceSample x, y;
        if (!s.evaluate(t, w[1], w[2], x) || !s.evaluate(size_t(o), wo[1], wo[2], y)) return 1e9;
        EXPECT_LT(distance(x.point, y.point), 1e-12);
        worst = std::max(worst, angle(x.normal, y.normal));
      }
    }
  return worst;
}

TEST(LoopSurface, NormalsAreContinuousAcrossEdgesOfRegularPatches) {
  const Mesh m = regular_torus(12, 8, 2.0, 0.7);
  auto s = loop(m);
  ASSERT_TRUE(s);
  EXPECT_LT(largest_normal_gap(m, *s, 7), 1e-9);
}

TEST(LoopSurface, NormalsAreContinuousAcrossEdgesNearIrregularVertices) {
  // Near valence-5 vertices OpenSubdiv uses Gregory triangles (end caps),
  // built to be tangent continuous across edges; samples reach 1/128 of an
  // edge from the vertex, inside the end caps of isolation 2 and 8.
  const Mesh m = icosahedron(0.05);
  for (int isolation : {2, 8}) {
    auto s = loop(m, isolation);
    ASSERT_TRUE(s);
    EXPECT_LT(largest_normal_gap(m, *s, 64), 1e-9) << "isolation " << isolation;
  }
}

TEST(LoopSurface, NormalsPointOutwardLikeTheBaseTriangles) {
  const Mesh m = icosahedron(0.0);
  auto s = loop(m);
  ASSERT_TRUE(s);
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    SurfaceSample x;
    ASSERT_TRUE(s->evaluate(t, 0.25, 0.25, x));
    const double r = std::sqrt(x.point[0] * x.point[0] + x.point[1] * x.point[1] + x.point[2] * x.point[2]);
    EXPECT_GT((x.normal[0] * x.point[0] + x.normal[1] * x.point[1] + x.normal[2] * x.point[2]) / r, 0.9);
  }
}

TEST(LoopSurface, RefusesBadInputWithAMessage) {
  std::string error;
  Mesh empty;
  EXPECT_FALSE(make_loop_surface(empty, {}, error));
  EXPECT_NE(error.find("no triangles"), std::string::npos) << error;
  Mesh bad = octahedron();
  bad.triangles[4] = 99;
  EXPECT_FALSE(make_loop_surface(bad, {}, error));
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;
  LoopOptions o;
  o.isolation = 0;
  EXPECT_FALSE(make_loop_surface(octahedron(), o, error));
  auto s = loop(octahedron());
  SurfaceSample x;
  EXPECT_FALSE(s->evaluate(0, 0.7, 0.7, x));
  EXPECT_FALSE(s->evaluate(8, 0.1, 0.1, x));
}

}  // namespace
}  // namespace isoform::test
