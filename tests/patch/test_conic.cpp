// The conic curve scheme (Hamann 1991, Section 6.2) on data whose answer is
// known: circular arcs for isosceles data (Theorem 6.3), the finite limit for
// parallel tangents (6.12), straight lines for flat data, an inflection and
// no loop for non-convex data (Definition 6.3), continuity in the angles.
#include <gtest/gtest.h>

#include <cmath>

#include "libcore/patch/conic.h"
#include "libcore/patch/edge_curve.h"

namespace isoform::patch {
namespace {

V3d on_circle(double angle) { return {std::cos(angle), std::sin(angle), 0.0}; }

double max_radius_error(const Conic<double>& c) {
  double worst = 0.0;
  for (int i = 0; i <= 100; ++i) worst = std::max(worst, std::abs(norm(conic_point(c, i / 100.0)) - 1.0));
  return worst;
}

TEST(Conic, IsoscelesDataGiveACircularArc) {
  for (double angle : {0.2, 1.0, 2.0, 2.9}) {
    SCOPED_TRACE(angle);
    const V3d a = on_circle(0.4), b = on_circle(0.4 + angle);
    const Conic<double> c = make_conic(a, a, b, b, 0.0);
    EXPECT_EQ(c.flags, 0);
    EXPECT_LT(max_radius_error(c), 1e-13);
    // omega = cos(alpha) with alpha = angle / 2 between tangent and chord.
    EXPECT_NEAR(c.w, (1.0 + 2.0 * std::cos(angle / 2)) / 3.0, 1e-14);
  }
}

TEST(Conic, ParallelTangentsHaveTheFiniteLimitOf612) {
  // A half circle: gamma = 0, L01 = L sin(beta) = 2.
  const V3d a = on_circle(0.0), b = on_circle(M_PI);
  const Conic<double> c = make_conic(a, a, b, b, 0.0);
  EXPECT_NEAR(norm(c.b[1] - c.b[0]), 2.0, 1e-12);
  EXPECT_NEAR(norm(c.b[2] - c.b[3]), 2.0, 1e-12);
  EXPECT_LT(max_radius_error(c), 1e-12);
  // Beyond parallel the curve stays finite.
  const Conic<double> d = make_conic(a, a, on_circle(M_PI + 0.3), on_circle(M_PI + 0.3), 0.0);
  EXPECT_LT(norm(d.b[1] - d.b[0]), 4.0);
}

TEST(Conic, FlatDataGiveAStraightLineWithLinearParameter) {
  const V3d a(0, 0, 0), b(2, 1, 0), n(0, 0, 1);
  const Conic<double> c = make_conic(a, n, b, n, 0.0);
  for (int i = 0; i <= 10; ++i) {
    const V3d p = conic_point(c, i / 10.0);
    const V3d q = a + (i / 10.0) * (b - a);
    EXPECT_LT(norm(p - q), 1e-14);
  }
}

TEST(Conic, NearlyStraightDataKeepTheirInteriorPointsNearThirds) {
  // Normals equal up to float noise (1e-8 rad, in unequal amounts): the
  // printed ratios sin(beta) / cos(gamma/2) would put b2 on b3 here.
  const V3d a(0, 0, 0), b(1, 0, 0);
  const Conic<double> c = make_conic(a, unit(V3d(-1e-9, 0, 1)), b, unit(V3d(-3e-8, 0, 1)), 0.0);
  EXPECT_NEAR(norm(c.b[1] - c.b[0]), 1.0 / 3, 1e-3);
  EXPECT_NEAR(norm(c.b[3] - c.b[2]), 1.0 / 3, 1e-3);
}

TEST(Conic, NonConvexDataGiveOneInflectionAndNoLoop) {
  // Both end tangents rise 0.5 rad above the chord: an S-curve.
  const double a = 0.5;
  const V3d n(-std::sin(a), 0.0, std::cos(a));
  const V3d b0(0, 0, 0), b3(1, 0, 0);
  const Conic<double> c = make_conic(b0, n, b3, n, 0.0);
  EXPECT_TRUE(c.flags & kConicNonConvex);
  int sign_changes = 0;
  double last_turn = 0.0;
  for (int i = 0; i < 200; ++i) {
    const V3d t1 = conic_eval(c, i / 200.0).tangent, t2 = conic_eval(c, (i + 1) / 200.0).tangent;
    EXPECT_GT(t1.x, 0.0) << "the curve turns back (a loop) at t = " << i / 200.0;
    const double turn = cross(t1, t2).y;
    if (last_turn != 0.0 && turn * last_turn < 0.0) ++sign_changes;
    if (turn != 0.0) last_turn = turn;
  }
  EXPECT_EQ(sign_changes, 1);
  // Def. 6.3: b1 - b0 and b3 - b2 point along the given tangents.
  const V3d t(std::cos(a), 0.0, std::sin(a));
  EXPECT_GT(dot(c.b[1] - c.b[0], t), 0.0);
  EXPECT_LT(norm(cross(c.b[1] - c.b[0], t)), 1e-14);
  EXPECT_GT(dot(c.b[3] - c.b[2], t), 0.0);
}

TEST(Conic, ConstructionIsContinuousAcrossTheConvexSwitch) {
  // The end tangent at b3 passes through the chord direction.
  const V3d b0(0, 0, 0), b3(1, 0, 0), n0(-0.4, 0, std::sqrt(1 - 0.16));
  auto at = [&](double angle) {
    return make_conic(b0, n0, b3, V3d(-std::sin(angle), 0, std::cos(angle)), 0.0);
  };
  const Conic<double> lo = at(-1e-7), hi = at(1e-7);
  EXPECT_NE(lo.flags & kConicNonConvex, hi.flags & kConicNonConvex);
  for (int i = 0; i < 4; ++i) EXPECT_LT(norm(lo.b[i] - hi.b[i]), 1e-6);
  EXPECT_LT(std::abs(lo.w - hi.w), 1e-6);
}

TEST(Conic, ReversedDataGiveTheSameCurve) {
  const V3d a(0, 0, 0), b(1, 0.2, 0.1);
  const V3d na = unit(V3d(-0.3, 0.1, 1)), nb = unit(V3d(0.4, -0.2, 1));
  const Conic<double> f = make_conic(a, na, b, nb, 0.0), r = make_conic(b, nb, a, na, 0.0);
  for (int i = 0; i <= 10; ++i) EXPECT_LT(norm(conic_point(f, i / 10.0) - conic_point(r, 1 - i / 10.0)), 1e-14);
}

TEST(Conic, LowerWeightsPullTowardTheChord) {
  const V3d a = on_circle(0.0), b = on_circle(1.5);
  double last = 1.0;
  for (double w : {0.0, 0.5, 0.2, 0.05}) {
    const V3d mid = conic_point(make_conic(a, a, b, b, w == 0.0 ? 0.0 : 1.0 / w), 0.5);
    EXPECT_LT(norm(mid), last + 1e-15) << "omega " << w;
    last = norm(mid);
  }
  EXPECT_GT(last, std::cos(0.75));  // still outside the chord's midpoint
}

TEST(Conic, OppositeNormalsGiveAFiniteCurve) {
  const V3d a(0, 0, 0), b(1, 0, 0), n(0, 0.6, 0.8);
  const Conic<double> c = make_conic(a, n, b, -n, 0.0);
  EXPECT_TRUE(c.flags & kConicOppositeNormals);
  for (int i = 0; i <= 10; ++i) {
    const V3d p = conic_point(c, i / 10.0);
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
  }
}

TEST(EdgeCurve, NormalsInterpolateTheEndsAndStayPerpendicular) {
  const V3d a(0, 0, 0), b(1, 0.2, 0.1);
  const V3d na = unit(V3d(-0.3, 0.5, 1)), nb = unit(V3d(0.4, -0.6, 1));
  const EdgeCurve e = make_edge_curve(a, na, b, nb, 0.0);
  EXPECT_LT(norm(edge_eval(e, 0.0).normal - na), 1e-14);
  EXPECT_LT(norm(edge_eval(e, 1.0).normal - nb), 1e-14);
  V3d last = na;
  for (int i = 0; i <= 50; ++i) {
    const double t = i / 50.0;
    const EdgeValue<double> v = edge_eval(e, t);
    EXPECT_NEAR(norm(v.normal), 1.0, 1e-14);
    EXPECT_LT(std::abs(dot(v.normal, unit(conic_eval(e.conic, t).tangent))), 1e-14);  // (6.13)
    EXPECT_LT(norm(v.normal - last), 0.05);  // continuous: no jump (the printed (6.16) jumps)
    last = v.normal;
  }
}

}  // namespace
}  // namespace isoform::patch
