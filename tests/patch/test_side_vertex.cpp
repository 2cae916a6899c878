// The side-vertex surface (Hamann 1991, Chapter 6) on inputs made in code:
// Figure 6.7's tetrahedron, exact interpolation, planar data, exact
// derivatives, tangent-plane continuity across every edge, both blends, and
// the refusals of bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "libcore/patch/side_vertex_surface.h"
#include "patch_fixtures.h"

namespace isoform::patch {
namespace {

using test::icosahedron;
using test::skewed_octahedron;
using test::tetrahedron;

std::unique_ptr<SideVertexSurface> surface(const Mesh& m, const PatchOptions& o = {}) {
  return std::make_unique<SideVertexSurface>(m, o);
}

V3d sample_point(const SideVertexSurface& s, size_t t, double u, double v) {
  SurfaceSample x;
  EXPECT_TRUE(s.evaluate(t, u, v, x)) << "triangle " << t << " at " << u << ", " << v;
  return V3d::from(x.point);
}

struct Distance {
  double max = 0.0, rms = 0.0, centre = 0.0, max_outside = 0.0;
};

// Distance from the unit sphere over a barycentric grid of n steps.
Distance sphere_distance(const SideVertexSurface& s, int n) {
  Distance d;
  double sum = 0.0;
  long count = 0;
  for (size_t t = 0; t < s.triangle_count(); ++t)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double r = norm(sample_point(s, t, double(i) / n, double(j) / n));
        d.max = std::max(d.max, std::abs(r - 1.0));
        d.max_outside = std::max(d.max_outside, r - 1.0);
        sum += (r - 1.0) * (r - 1.0);
        ++count;
      }
  d.rms = std::sqrt(sum / double(count));
  d.centre = 1.0 - norm(sample_point(s, 0, 1.0 / 3, 1.0 / 3));
  return d;
}

TEST(SideVertex, Figure67TetrahedronTouchesTheSphereAlongTheEdges) {
  for (Blend b : {Blend::Printed, Blend::Squared}) {
    PatchOptions o;
    o.blend = b;
    const auto s = surface(tetrahedron(), o);
    // The edges are great arcs: the boundary conics are circles.
    for (size_t t = 0; t < 4; ++t)
      for (int i = 0; i <= 20; ++i) {
        EXPECT_NEAR(norm(sample_point(*s, t, i / 20.0, 0.0)), 1.0, 1e-13);
        EXPECT_NEAR(norm(sample_point(*s, t, 0.0, i / 20.0)), 1.0, 1e-13);
        EXPECT_NEAR(norm(sample_point(*s, t, i / 20.0, 1 - i / 20.0)), 1.0, 1e-13);
      }
    const Distance d = sphere_distance(*s, 60);
    std::printf("Figure 6.7, %s blend, automatic weights: max distance %.6f, RMS %.6f, at the face centre %.6f\n",
                b == Blend::Printed ? "printed" : "squared", d.max, d.rms, d.centre);
    // Inside the sphere, farthest at the face centres, as the construction
    // read faithfully gives (the text beside Figure 6.7 says only "maximal
    // distance ... about 0.01"; the construction is not tuned to that).
    EXPECT_LT(d.max_outside, 1e-12);
    EXPECT_NEAR(d.centre, d.max, 1e-12);
    EXPECT_GT(d.max, 1e-4);
  }
}

TEST(SideVertex, Figure67LowerWeightsPullTowardTheTetrahedron) {
  double last_centre = 1.0, last_edge = 1.0;
  for (double w : {0.0, 0.4, 0.2, 0.1}) {
    PatchOptions o;
    o.tension = w;
    const auto s = surface(tetrahedron(), o);
    const double centre = norm(sample_point(*s, 0, 1.0 / 3, 1.0 / 3));
    const double edge = norm(sample_point(*s, 0, 0.5, 0.0));
    std::printf("Figure 6.7, omega %s: face centre at radius %.6f, edge midpoint at %.6f\n",
                w == 0.0 ? "auto" : std::to_string(w).c_str(), centre, edge);
    EXPECT_LT(centre, last_centre);
    EXPECT_LT(edge, last_edge + 1e-15);
    EXPECT_GT(centre, 1.0 / 3.0);  // the tetrahedron's face centre
    last_centre = centre;
    last_edge = edge;
  }
}

TEST(SideVertex, InterpolatesVerticesAndNormalsExactly) {
  const Mesh m = skewed_octahedron();
  for (Blend b : {Blend::Printed, Blend::Squared}) {
    PatchOptions o;
    o.blend = b;
    const auto s = surface(m, o);
    for (size_t t = 0; t < s->triangle_count(); ++t) {
      const double corners[3][2] = {{0, 0}, {1, 0}, {0, 1}};
      for (int i = 0; i < 3; ++i) {
        SurfaceSample x;
        ASSERT_TRUE(s->evaluate(t, corners[i][0], corners[i][1], x));
        const size_t vi = size_t(m.triangles[3 * t + i]);
        EXPECT_EQ(V3d::from(x.point).x, m.precise_points[3 * vi]);
        EXPECT_LT(norm(V3d::from(x.point) - s->vertex(vi)), 1e-15);
        EXPECT_LT(norm(V3d::from(x.normal) - s->vertex_normal(vi)), 1e-12);
        // Next to the corner the exact normal tends to the data normal.
        const double eps = 1e-7;
        SurfaceSample y;
        const double u = corners[i][0] == 1 ? 1 - 2 * eps : eps, v = corners[i][1] == 1 ? 1 - 2 * eps : eps;
        ASSERT_TRUE(s->evaluate(t, u, v, y));
        EXPECT_LT(norm(V3d::from(y.normal) - s->vertex_normal(vi)), 1e-4);
      }
    }
  }
}

TEST(SideVertex, PlanarDataGiveThePlanarTriangle) {
  Mesh m;
  m.precise_points = {0, 0, 0, 2, 0.3, 0, 0.4, 1.5, 0};
  m.points.assign(m.precise_points.begin(), m.precise_points.end());
  m.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  m.triangles = {0, 1, 2};
  const auto s = surface(m);
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; i + j <= 10; ++j) {
      const double u = i / 10.0, v = j / 10.0;
      SurfaceSample x;
      ASSERT_TRUE(s->evaluate(0, u, v, x));
      const V3d flat = (1 - u - v) * s->vertex(0) + u * s->vertex(1) + v * s->vertex(2);
      EXPECT_LT(norm(V3d::from(x.point) - flat), 1e-14);
      EXPECT_LT(norm(V3d::from(x.normal) - V3d(0, 0, 1)), 1e-14);
    }
}

// Central differences of the exact points against the jets' derivatives.
TEST(SideVertex, DerivativesAreExact) {
  const auto s = surface(skewed_octahedron());
  const double h = 1e-5;
  for (size_t t = 0; t < s->triangle_count(); ++t)
    for (const auto& uv : {std::pair<double, double>{0.2, 0.3}, {0.6, 0.1}, {0.05, 0.9}, {0.45, 0.45}}) {
      const double u = uv.first, v = uv.second;
      SurfaceSample x;
      ASSERT_TRUE(s->evaluate(t, u, v, x));
      ASSERT_TRUE(x.has_second);
      auto p = [&](double a, double b) { return sample_point(*s, t, a, b); };
      const V3d du = (1 / (2 * h)) * (p(u + h, v) - p(u - h, v));
      const V3d dv = (1 / (2 * h)) * (p(u, v + h) - p(u, v - h));
      const V3d duu = (1 / (h * h)) * (p(u + h, v) - 2.0 * p(u, v) + p(u - h, v));
      const V3d dvv = (1 / (h * h)) * (p(u, v + h) - 2.0 * p(u, v) + p(u, v - h));
      const V3d duv = (1 / (4 * h * h)) * (p(u + h, v + h) - p(u + h, v - h) - p(u - h, v + h) + p(u - h, v - h));
      EXPECT_LT(norm(du - V3d::from(x.du)), 1e-7);  // O(h^2) truncation
      EXPECT_LT(norm(dv - V3d::from(x.dv)), 1e-7);
      EXPECT_LT(norm(duu - V3d::from(x.duu)), 1e-4);
      EXPECT_LT(norm(duv - V3d::from(x.duv)), 1e-4);
      EXPECT_LT(norm(dvv - V3d::from(x.dvv)), 1e-4);
    }
}

// Along every interior edge both patches have the same normal (the boundary
// normal n_S) at sampled points; returns the largest angle in radians.
double largest_edge_normal_gap(const SideVertexSurface& s, const Mesh& m, int samples) {
  double worst = 0.0;
  for (size_t t = 0; t < m.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int32_t other = m.neighbours[3 * t + i];
      if (other < 0 || size_t(other) < t) continue;
      const int32_t a = m.triangles[3 * t + i], b = m.triangles[3 * t + (i + 1) % 3];
      auto at = [&](size_t tri, int32_t from, int32_t to, double f, SurfaceSample& x) {
        double bary[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k) {
          if (m.triangles[3 * tri + k] == from) bary[k] = 1 - f;
          if (m.triangles[3 * tri + k] == to) bary[k] = f;
        }
        return s.evaluate(tri, bary[1], bary[2], x);
      };
      for (int k = 1; k < samples; ++k) {
        const double f = double(k) / samples;
        SurfaceSample x, y;
        EXPECT_TRUE(at(t, a, b, f, x) && at(size_t(other), a, b, f, y));
        EXPECT_LT(norm(V3d::from(x.point) - V3d::from(y.point)), 1e-12);
        const double c = std::min(1.0, dot(V3d::from(x.normal), V3d::from(y.normal)));
        worst = std::max(worst, norm(cross(V3d::from(x.normal), V3d::from(y.normal))));
        EXPECT_GT(c, 0.0);
      }
    }
  return worst;
}

TEST(SideVertex, TangentPlaneContinuousAcrossEveryEdge) {
  for (const Mesh& m : {icosahedron(), skewed_octahedron(), tetrahedron()})
    for (Blend b : {Blend::Printed, Blend::Squared}) {
      PatchOptions o;
      o.blend = b;
      EXPECT_LT(largest_edge_normal_gap(*surface(m, o), m, 16), 1e-9);
      o.tension = 0.3;
      EXPECT_LT(largest_edge_normal_gap(*surface(m, o), m, 16), 1e-9);
    }
}

TEST(SideVertex, PerEdgeWeightsKeepTangentPlaneContinuity) {
  const Mesh m = icosahedron();
  PatchOptions o;
  o.edge_tension = {{0, 11, 0.2}, {5, 0, 0.9}, {3, 9, 0.05}};
  const auto s = surface(m, o);
  EXPECT_LT(largest_edge_normal_gap(*s, m, 16), 1e-9);
  // The weighted edge lies lower than an automatic one.
  const auto plain = surface(m);
  SurfaceSample x, y;
  ASSERT_TRUE(s->evaluate(0, 0.5, 0.0, x));  // triangle 0 = (0, 11, 5): edge 0-11
  ASSERT_TRUE(plain->evaluate(0, 0.5, 0.0, y));
  EXPECT_LT(norm(V3d::from(x.point)), norm(V3d::from(y.point)) - 1e-3);
}

TEST(SideVertex, BadInputIsRefusedWithAMessage) {
  std::string error;
  Mesh m = tetrahedron();
  m.normals.clear();
  EXPECT_EQ(make_side_vertex_surface(m, {}, error), nullptr);
  EXPECT_NE(error.find("no vertex normals"), std::string::npos) << error;
  m = tetrahedron();
  m.normals[3] = m.normals[4] = m.normals[5] = 0.0f;
  EXPECT_EQ(make_side_vertex_surface(m, {}, error), nullptr);
  EXPECT_NE(error.find("normal of vertex 1"), std::string::npos) << error;
  m = tetrahedron();
  m.triangles[1] = m.triangles[0];
  EXPECT_EQ(make_side_vertex_surface(m, {}, error), nullptr);
  EXPECT_NE(error.find("triangle 0 is degenerate"), std::string::npos) << error;
  m = tetrahedron();
  PatchOptions o;
  o.tension = -1;
  EXPECT_EQ(make_side_vertex_surface(m, o, error), nullptr);
  EXPECT_NE(error.find("tension"), std::string::npos) << error;
  o = {};
  o.edge_tension = {{0, 7, 0.5}};
  EXPECT_EQ(make_side_vertex_surface(m, o, error), nullptr);
  EXPECT_NE(error.find("no such edge"), std::string::npos) << error;
  EXPECT_NE(make_side_vertex_surface(tetrahedron(), {}, error), nullptr);
  EXPECT_TRUE(error.empty());
  // Outside the triangle: undefined, not a guess.
  SurfaceSample x;
  const auto s = surface(tetrahedron());
  EXPECT_FALSE(s->evaluate(0, 0.7, 0.5, x));
  EXPECT_FALSE(s->evaluate(0, -0.1, 0.5, x));
  EXPECT_FALSE(s->evaluate(4, 0.1, 0.1, x));
}

TEST(SideVertex, OppositeNormalsOnAnEdgeGiveFiniteSamples) {
  Mesh m = tetrahedron();
  for (int a = 0; a < 3; ++a) m.normals[3 + a] = -m.normals[a];  // vertex 1 = -vertex 0
  const auto s = surface(m);
  EXPECT_GE(s->stats().opposite_normal_edges, 1);
  for (size_t t = 0; t < 4; ++t)
    for (int i = 0; i <= 8; ++i)
      for (int j = 0; i + j <= 8; ++j) {
        V3d p;
        EXPECT_TRUE(s->point(t, i / 8.0, j / 8.0, p));
      }
}

}  // namespace
}  // namespace isoform::patch
