// The batch evaluation (batch_eval.h: shared radial conics, four samples per
// vector) against the reference (patch_eval.h) and the one-sample fast path:
// the same point, derivatives and normal to rounding, on both lane paths
// (AVX2 where the CPU has it, and SSE2), in shuffled order with repeated
// samples, over corners, edges and the inside, and with out-of-range input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "libcore/patch/batch_eval.h"
#include "libcore/patch/lanes_jet.h"
#include "libcore/patch/side_vertex_surface.h"
#include "patch_fixtures.h"

namespace isoform::patch {
namespace {

using test::icosahedron;
using test::skewed_octahedron;
using test::tetrahedron;

double relative(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const V3d x = V3d::from(a), y = V3d::from(b);
  return norm(x - y) / std::max(1.0, norm(y));
}

struct Worst {
  double point = 0, first = 0, second = 0, normal = 0;
  long samples = 0, lattice = 0;
};

// Every triangle's barycentric grid of n steps (corners and edges
// included), each sample twice, shuffled, evaluated as one batch per
// triangle; compared with the reference (inside) and evaluate_order (all).
Worst compare_batch(const SideVertexSurface& s, int n, bool second, BatchIsa isa) {
  std::vector<double> u, v;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      for (int twice = 0; twice < 2; ++twice) {
        u.push_back(double(i) / n);
        v.push_back(double(j) / n);
      }
  std::vector<size_t> order(u.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::shuffle(order.begin(), order.end(), std::mt19937(5));
  std::vector<double> su(u.size()), sv(u.size());
  for (size_t k = 0; k < order.size(); ++k) su[k] = u[order[k]], sv[k] = v[order[k]];
  Worst w;
  w.lattice = long(u.size());
  std::vector<SurfaceSample> out(u.size());
  std::unique_ptr<bool[]> ok(new bool[u.size()]);
  // One plan for every triangle, made for the default blend (a surface
  // with the other blend gets a plan of its own per call).
  const BatchPlan plan(PatchOptions{}, su.data(), sv.data(), su.size());
  for (size_t t = 0; t < s.triangle_count(); ++t) {
    evaluate_batch(s, t, plan, out.data(), ok.get(), second, isa);
    for (size_t k = 0; k < su.size(); ++k) {
      SurfaceSample f, r;
      const bool fast_ok = s.evaluate_order(t, su[k], sv[k], f, second);
      EXPECT_EQ(ok[k], fast_ok) << "triangle " << t << " at " << su[k] << ", " << sv[k];
      if (!ok[k] || !fast_ok) continue;
      const SurfaceSample& b = out[k];
      EXPECT_EQ(b.has_second, f.has_second);
      // Corners and edges of the reference are the fast path's rules; the
      // reference itself is compared where it is evaluated by its blend.
      const bool corner = (su[k] == 0 && sv[k] == 0) || su[k] == 1 || sv[k] == 1;
      if (!corner) {
        EXPECT_TRUE(s.evaluate_reference(t, su[k], sv[k], r, second));
      } else {
        r = f;
      }
      ++w.samples;
      w.point = std::max({w.point, relative(b.point, r.point), relative(b.point, f.point)});
      w.first = std::max({w.first, relative(b.du, r.du), relative(b.dv, r.dv), relative(b.du, f.du)});
      w.normal = std::max({w.normal, relative(b.normal, r.normal), relative(b.normal, f.normal)});
      if (second)
        w.second = std::max({w.second, relative(b.duu, r.duu), relative(b.duv, r.duv), relative(b.dvv, r.dvv)});
    }
  }
  return w;
}

void expect_equal(const Mesh& m, const PatchOptions& o, const char* what) {
  const SideVertexSurface s(m, o);
  for (BatchIsa isa : {BatchIsa::Best, BatchIsa::Baseline})
    for (bool second : {true, false}) {
      const Worst w = compare_batch(s, 12, second, isa);
      EXPECT_EQ(w.samples, w.lattice * long(s.triangle_count())) << what;
      EXPECT_LT(w.point, 1e-14) << what;
      EXPECT_LT(w.first, 1e-12) << what;
      EXPECT_LT(w.second, 1e-9) << what;
      EXPECT_LT(w.normal, 1e-11) << what;
    }
}

TEST(Batch, EqualsTheReferenceOnBothBlendsAndTensions) {
  for (Blend b : {Blend::Squared, Blend::Printed})
    for (double tension : {0.0, 0.3}) {
      PatchOptions o;
      o.blend = b;
      o.tension = tension;
      expect_equal(tetrahedron(), o, "tetrahedron");
      expect_equal(icosahedron(), o, "icosahedron");
      expect_equal(skewed_octahedron(), o, "skewed octahedron");
    }
}

TEST(Batch, EqualsTheReferenceWithPerEdgeWeights) {
  PatchOptions o;
  o.edge_tension = {{0, 11, 0.2}, {5, 0, 0.9}, {3, 9, 0.05}};
  expect_equal(icosahedron(), o, "icosahedron, per-edge weights");
}

TEST(Batch, EqualsTheReferenceOnNonConvexAndOppositeNormals) {
  Mesh m = skewed_octahedron();
  for (int a = 0; a < 3; ++a) m.normals[size_t(a)] = -0.3f * m.normals[size_t(a)] + 0.2f * float(a);
  expect_equal(m, {}, "non-convex data");
  m = tetrahedron();
  for (int a = 0; a < 3; ++a) m.normals[size_t(3 + a)] = -m.normals[size_t(a)];
  expect_equal(m, {}, "opposite normals");
}

TEST(Batch, RefusesWhatEvaluateRefuses) {
  const SideVertexSurface s(icosahedron(), {});
  const double u[5] = {-0.1, 0.7, 0.2, NAN, 0.25};
  const double v[5] = {0.2, 0.6, -1e-9, 0.1, 0.25};
  SurfaceSample out[5];
  bool ok[5];
  evaluate_batch(s, 0, u, v, 5, out, ok, true);
  EXPECT_FALSE(ok[0]);
  EXPECT_FALSE(ok[1]);
  EXPECT_FALSE(ok[2]);
  EXPECT_FALSE(ok[3]);
  EXPECT_TRUE(ok[4]);
  evaluate_batch(s, s.triangle_count(), u + 4, v + 4, 1, out, ok, true);
  EXPECT_FALSE(ok[0]);
}

// The lanes' sin and cos (polynomials after reduction by pi/2) against libm,
// over the turn angles' range and beyond, across every quadrant.
TEST(Batch, LaneSinCosMatchLibm) {
  double worst = 0.0;
  long checked = 0;
  for (int k = -40000; k <= 40000; k += 4) {
    lanes::L x;
    for (int l = 0; l < 4; ++l) x[l] = 7.0 * double(k + l) / 40000.0 + 1e-3 * l;
    lanes::L s, c;
    lanes::lane_sincos(x, s, c);
    for (int l = 0; l < 4; ++l) {
      worst = std::max({worst, std::abs(s[l] - std::sin(x[l])), std::abs(c[l] - std::cos(x[l]))});
      ++checked;
    }
  }
  EXPECT_EQ(checked, 80004);
  EXPECT_LT(worst, 4e-16);
  lanes::L s, c;
  lanes::lane_sincos(lanes::L{0.0, M_PI_2, M_PI, -M_PI_2}, s, c);
  EXPECT_EQ(s[0], 0.0);
  EXPECT_EQ(c[0], 1.0);
  EXPECT_NEAR(s[1], 1.0, 1e-16);
  EXPECT_NEAR(c[2], -1.0, 1e-16);
  EXPECT_NEAR(s[3], -1.0, 1e-16);
}

}  // namespace
}  // namespace isoform::patch
