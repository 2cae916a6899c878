// Theorem 5.3's half-plane test and the one-turn condition (half_plane.h)
// on hand-checked polygons.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "libcore/reduce/half_plane.h"

namespace isoform::reduce {
namespace {

using Ring = std::vector<Eigen::Vector2d>;

bool once(const Eigen::Vector2d& q, const Ring& ring, bool closed) {
  const int n = int(ring.size());
  return half_plane_once(q, n, closed ? n : n - 1, [&](int j) { return ring[size_t(j)]; });
}

// The regular polygon of n corners around the origin, going round `turns`
// times (a star polygon {n/turns} when turns > 1), counter-clockwise.
// (5.17) alone, as the seed asks it: q strictly left of every edge.
bool seed_test(const Eigen::Vector2d& q, const Ring& ring, bool closed) {
  const int n = int(ring.size());
  for (int j = 0; j < (closed ? n : n - 1); ++j) {
    const Eigen::Vector2d yj = ring[size_t(j)], d = ring[size_t((j + 1) % n)] - yj;
    if (!(-d(1) * (q(0) - yj(0)) + d(0) * (q(1) - yj(1)) > 1e-12 * d.squaredNorm())) return false;
  }
  return true;
}

Ring rotated(const Ring& r, double angle) {
  Ring out;
  const double c = std::cos(angle), s = std::sin(angle);
  for (const auto& y : r) out.push_back({c * y(0) - s * y(1), s * y(0) + c * y(1)});
  return out;
}

Ring around(int n, int turns, double radius = 1.0) {
  Ring r;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * turns * k / n;
    r.push_back({radius * std::cos(a), radius * std::sin(a)});
  }
  return r;
}

TEST(HalfPlane, ConvexPolygonSeenFromInsideOnly) {
  const Ring square{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  EXPECT_TRUE(once({0, 0}, square, true));
  EXPECT_TRUE(once({0.9, -0.9}, square, true));
  EXPECT_FALSE(once({1.5, 0}, square, true));   // outside: right of the edge x = 1
  EXPECT_FALSE(once({1.0, 0}, square, true));   // on an edge's line
  Ring clockwise(square.rbegin(), square.rend());
  EXPECT_FALSE(once({0, 0}, clockwise, true));
}

// A pentagram {5/2} and a heptagram {7/2} go round the centre twice: every
// edge has the centre on its left (the seed's test alone passes them), but
// the fan from the centre would cover the plane twice.
TEST(HalfPlane, PolygonsGoingRoundTwiceAreRefused) {
  for (int n : {5, 7, 9, 13}) {
    const Ring twice = around(n, 2);
    const Eigen::Vector2d centre(0, 0);
    for (int j = 0; j < n; ++j) {  // the seed's inequalities (5.17) all hold
      const Eigen::Vector2d a = twice[size_t(j)], b = twice[size_t((j + 1) % n)];
      ASSERT_GT(a(0) * b(1) - a(1) * b(0), 0.0) << n << " " << j;
    }
    EXPECT_FALSE(once(centre, twice, true)) << n;
    EXPECT_TRUE(once(centre, around(n, 1), true)) << n;
    EXPECT_TRUE(once({0.1, -0.05}, around(n, 1), true)) << n;
    EXPECT_FALSE(once({0.1, -0.05}, twice, true)) << n;
    // Where the first corner lies does not matter: the same star rotated.
    Ring shifted(twice.begin() + 2, twice.end());
    shifted.insert(shifted.end(), twice.begin(), twice.begin() + 2);
    EXPECT_FALSE(once(centre, shifted, true)) << n;
  }
  EXPECT_FALSE(once({0, 0}, around(11, 3), true));
}

// An open corona's path: its fan sweeps from the first corner to the last
// and must stay within one turn, wherever the path starts.
TEST(HalfPlane, OpenPathMustSweepLessThanATurn) {
  const Ring half{{1, 0}, {0, 1}, {-1, 0}};  // a half turn
  EXPECT_TRUE(once({0, 0}, half, false));
  const Ring most = [] {  // 0 to 330 degrees
    Ring r;
    for (int k = 0; k <= 11; ++k) r.push_back({std::cos(k * M_PI / 6), std::sin(k * M_PI / 6)});
    return r;
  }();
  Ring beyond = most;  // on to 390 degrees: past the first corner's ray
  beyond.push_back({1, 0.001});
  beyond.push_back({std::cos(M_PI / 6), std::sin(M_PI / 6)});
  for (double start : {0.0, 0.3, 1.0, 2.0, M_PI, 4.0, 5.5, 2 * M_PI - 1e-9}) {
    EXPECT_TRUE(once({0, 0}, rotated(half, start), false)) << start;
    EXPECT_TRUE(once({0, 0}, rotated(most, start), false)) << start;
    EXPECT_FALSE(once({0, 0}, rotated(beyond, start), false)) << start;
  }
  // Exactly one turn, ending on the first corner's ray.
  EXPECT_FALSE(once({0, 0}, Ring{{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {2, 0}}, false));
  // Closed, the same corners up to 330 degrees go round once.
  EXPECT_TRUE(once({0, 0}, most, true));
}

// Corners on q's line (v = q_v) are passed once, on either side of q.
TEST(HalfPlane, CornersOnTheLineThroughThePoint) {
  const Ring diamond{{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  EXPECT_TRUE(once({0, 0}, diamond, true));
  Ring twice = diamond;
  twice.insert(twice.end(), diamond.begin(), diamond.end());
  EXPECT_FALSE(once({0, 0}, twice, true));
  EXPECT_TRUE(once({0, 0}, Ring{{0, -1}, {1, 0}, {0, 1}}, false));
  EXPECT_TRUE(once({0, 0}, Ring{{0, 1}, {-1, 0}, {0, -1}, {1, 0}}, false));
}

// A corner one rounding off the ray through the first corner (found by a
// review): the sides taken against that ray counted a second pass.
TEST(HalfPlane, CornerJustAfterTheFirstOnItsRay) {
  const Eigen::Vector2d q(-0.20183773334105504, -0.34613933155942278);
  const Ring ring{{-0.84990768643385961, 0.86945639263155683},
                  {-0.8500251625298173, 0.86967674452298349},
                  {-1.2968829733591691, -0.92994026406545383},
                  {0.48827669451733435, -1.640598585076197},
                  {1.0501838423834986, 0.32135031792170154}};
  ASSERT_TRUE(seed_test(q, ring, false));
  EXPECT_TRUE(once(q, ring, false));  // three quarters of a turn
  ASSERT_TRUE(seed_test(q, ring, true));
  EXPECT_TRUE(once(q, ring, true));
}

// Wherever the polygon goes round once, the answer is (5.17)'s: random
// polygons around q (corners at sorted random angles and radii), closed and
// as open paths of their first corners.
TEST(HalfPlane, OnceRoundTheAnswerIsTheSeedsTest) {
  std::mt19937 random(36);
  std::uniform_real_distribution<double> unit(0, 1);
  int closed_passed = 0, open_passed = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int n = 3 + int(unit(random) * 14);
    std::vector<double> angles;
    for (int k = 0; k < n; ++k) angles.push_back(2 * M_PI * unit(random));
    std::sort(angles.begin(), angles.end());
    const double scale = std::pow(10.0, 8 * unit(random) - 4);
    const Eigen::Vector2d q(scale * (unit(random) - 0.5) * 1e3, scale * (unit(random) - 0.5) * 1e3);
    Ring ring;
    for (double a : angles) {
      const double r = scale * (0.1 + 10 * unit(random));
      ring.push_back({q(0) + r * std::cos(a), q(1) + r * std::sin(a)});
    }
    const bool seed = seed_test(q, ring, true);
    EXPECT_EQ(once(q, ring, true), seed) << trial;
    closed_passed += seed ? 1 : 0;
    const Ring path(ring.begin(), ring.begin() + 2 + int(unit(random) * double(n - 1)));
    const bool open_seed = seed_test(q, path, false);
    EXPECT_EQ(once(q, path, false), open_seed) << trial;
    open_passed += open_seed ? 1 : 0;
  }
  EXPECT_GT(closed_passed, 2000);  // (the test is not empty)
  EXPECT_GT(open_passed, 5000);
}

}  // namespace
}  // namespace isoform::reduce
