// The fast evaluation (fast_eval.h: one-variable jets along the opposite
// edge, the radial cubic differentiated by hand) against the reference
// (patch_eval.h: the whole construction in two-variable jets): the same
// point, derivatives and normal to rounding, on skew, non-convex, weighted
// and opposite-normal data, inside the triangles and on their edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "libcore/patch/side_vertex_surface.h"
#include "patch_fixtures.h"

namespace isoform::patch {
namespace {

using test::icosahedron;
using test::skewed_octahedron;
using test::tetrahedron;

// |a - b| relative to max(1, |b|).
double relative(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const V3d x = V3d::from(a), y = V3d::from(b);
  return norm(x - y) / std::max(1.0, norm(y));
}

struct Worst {
  double point = 0, first = 0, second = 0, normal = 0;
  long samples = 0;
};

// Both paths over a barycentric grid of n steps (corners left out: both
// paths share the corner rule), both derivative orders.
Worst compare_paths(const SideVertexSurface& s, int n) {
  Worst w;
  for (size_t t = 0; t < s.triangle_count(); ++t)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        if ((i == 0 && j == 0) || i == n || j == n) continue;
        const double u = double(i) / n, v = double(j) / n;
        for (bool second : {true, false}) {
          SurfaceSample f, r;
          const bool fast_ok = s.evaluate_order(t, u, v, f, second);
          const bool ref_ok = s.evaluate_reference(t, u, v, r, second);
          EXPECT_EQ(fast_ok, ref_ok) << "triangle " << t << " at " << u << ", " << v;
          if (!fast_ok || !ref_ok) continue;
          EXPECT_EQ(f.has_second, r.has_second);
          ++w.samples;
          w.point = std::max(w.point, relative(f.point, r.point));
          w.first = std::max({w.first, relative(f.du, r.du), relative(f.dv, r.dv)});
          w.normal = std::max(w.normal, relative(f.normal, r.normal));
          if (second)
            w.second = std::max({w.second, relative(f.duu, r.duu), relative(f.duv, r.duv), relative(f.dvv, r.dvv)});
        }
      }
  return w;
}

void expect_equal_paths(const Mesh& m, const PatchOptions& o, const char* what) {
  const SideVertexSurface s(m, o);
  const Worst w = compare_paths(s, 12);
  EXPECT_GT(w.samples, 50L * long(s.triangle_count())) << what;
  EXPECT_LT(w.point, 1e-14) << what;
  EXPECT_LT(w.first, 1e-12) << what;
  EXPECT_LT(w.second, 1e-9) << what;
  EXPECT_LT(w.normal, 1e-11) << what;
}

TEST(FastPath, EqualsTheReferenceOnBothBlendsAndTensions) {
  for (Blend b : {Blend::Squared, Blend::Printed})
    for (double tension : {0.0, 0.3}) {
      PatchOptions o;
      o.blend = b;
      o.tension = tension;
      expect_equal_paths(tetrahedron(), o, "tetrahedron");
      expect_equal_paths(icosahedron(), o, "icosahedron");
      expect_equal_paths(skewed_octahedron(), o, "skewed octahedron");
    }
}

TEST(FastPath, EqualsTheReferenceWithPerEdgeWeights) {
  PatchOptions o;
  o.edge_tension = {{0, 11, 0.2}, {5, 0, 0.9}, {3, 9, 0.05}};
  expect_equal_paths(icosahedron(), o, "icosahedron, per-edge weights");
}

TEST(FastPath, EqualsTheReferenceOnNonConvexAndOppositeNormals) {
  // Vertex 0's normal turned inward past the face: its edges get inflections.
  Mesh m = skewed_octahedron();
  for (int a = 0; a < 3; ++a) m.normals[size_t(a)] = -0.3f * m.normals[size_t(a)] + 0.2f * float(a);
  const SideVertexSurface probe(m, {});
  EXPECT_GE(probe.stats().nonconvex_edges, 1);
  expect_equal_paths(m, {}, "non-convex data");
  m = tetrahedron();
  for (int a = 0; a < 3; ++a) m.normals[size_t(3 + a)] = -m.normals[size_t(a)];
  expect_equal_paths(m, {}, "opposite normals");
}

}  // namespace
}  // namespace isoform::patch
