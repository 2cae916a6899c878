// Theorem 5.3's half-plane test and the one-turn condition (half_plane.h)
// on hand-checked polygons.
#include <gtest/gtest.h>

#include <cmath>
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
// and must stay within one turn.
TEST(HalfPlane, OpenPathMustSweepLessThanATurn) {
  const Ring half{{1, 0}, {0, 1}, {-1, 0}};  // a half turn
  EXPECT_TRUE(once({0, 0}, half, false));
  const Ring most = [] {  // 0 to 330 degrees
    Ring r;
    for (int k = 0; k <= 11; ++k) r.push_back({std::cos(k * M_PI / 6), std::sin(k * M_PI / 6)});
    return r;
  }();
  EXPECT_TRUE(once({0, 0}, most, false));
  Ring beyond = most;  // on to 390 degrees: past the first corner's ray
  beyond.push_back({1, 0.001});
  beyond.push_back({std::cos(M_PI / 6), std::sin(M_PI / 6)});
  EXPECT_FALSE(once({0, 0}, beyond, false));
  // Closed, the same corners up to 330 degrees go round once.
  EXPECT_TRUE(once({0, 0}, most, true));
}

}  // namespace
}  // namespace isoform::reduce
