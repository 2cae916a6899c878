// Vertex colours (Figure 4.1): the whole-mesh fill, four vertices at a
// time, gives every vertex the one-vertex rule's bytes, and that rule maps
// the range's ends, its middle and flagged vertices to the maps' colours.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "libcore/curvature/curvature_colours.h"
#include "libcore/curvature/vertex_curvature.h"

using namespace isoform;

namespace {

// n vertices: mostly spread values, some exactly on the maps' segment ends
// after scaling, some extreme, every 7th flagged failed or isolated.
VertexCurvature curvature_of(size_t n, unsigned seed) {
  VertexCurvature c;
  std::mt19937 rng(seed);
  std::normal_distribution<float> spread(0.0f, 2.0f);
  for (size_t v = 0; v < n; ++v) {
    float x = spread(rng);
    if (v % 11 == 3) x = 0.0f;
    if (v % 13 == 5) x = 1e6f * (v % 2 ? 1.0f : -1.0f);
    c.mean.push_back(x);
    c.absolute.push_back(std::abs(x));
    c.flags.push_back(v % 7 == 6 ? (v % 14 == 6 ? kCurvatureFailed : kCurvatureIsolated) : 0);
  }
  c.k1 = c.k2 = c.gauss = c.mean;
  return c;
}

void expect_rule(const VertexCurvature& c, CurvatureQuantity q) {
  std::vector<uint8_t> colors;
  double lo = 0, hi = 0;
  curvature_colours(c, q, colors, &lo, &hi);
  const std::vector<float>& values = curvature_values(c, q);
  ASSERT_EQ(colors.size(), 4 * values.size());
  for (size_t v = 0; v < values.size(); ++v) {
    uint8_t one[4];
    curvature_colour(q, lo, hi, values[v], c.flags[v], one);
    for (int k = 0; k < 4; ++k) ASSERT_EQ(colors[4 * v + size_t(k)], one[k]) << "vertex " << v << " channel " << k;
  }
}

}  // namespace

TEST(CurvatureColours, EveryVertexGetsTheOneVertexRule) {
  for (size_t n : {1u, 2u, 3u, 4u, 5u, 6u, 7u, 203u, 4096u}) {
    const VertexCurvature c = curvature_of(n, unsigned(n));
    expect_rule(c, CurvatureQuantity::Mean);
    expect_rule(c, CurvatureQuantity::Absolute);
  }
}

TEST(CurvatureColours, AnEmptyRangeGivesTheMiddleColour) {
  VertexCurvature c;
  c.mean.assign(10, 0.0f);
  c.flags.assign(10, 0);
  c.k1 = c.k2 = c.gauss = c.absolute = c.mean;
  expect_rule(c, CurvatureQuantity::Mean);
  std::vector<uint8_t> colors;
  double lo, hi;
  curvature_colours(c, CurvatureQuantity::Mean, colors, &lo, &hi);
  for (size_t v = 0; v < 10; ++v) EXPECT_EQ(colors[4 * v], 222);  // 0.87 of 255, rounded
}

TEST(CurvatureColours, TheRuleMapsEndsMiddleAndFlags) {
  uint8_t out[4];
  // Diverging map on [-2, 2]: blue, light grey, red at -2, 0, 2.
  curvature_colour(CurvatureQuantity::Mean, -2, 2, -2.0f, 0, out);
  EXPECT_EQ(out[0], 59);   // 0.23 * 255 = 58.65
  EXPECT_EQ(out[1], 77);   // 0.30 * 255 = 76.5, half away from zero
  EXPECT_EQ(out[2], 191);  // 0.75 * 255 = 191.25
  EXPECT_EQ(out[3], 255);
  curvature_colour(CurvatureQuantity::Mean, -2, 2, 0.0f, 0, out);
  EXPECT_EQ(out[0], 222);
  EXPECT_EQ(out[1], 222);
  EXPECT_EQ(out[2], 222);
  curvature_colour(CurvatureQuantity::Mean, -2, 2, 5.0f, 0, out);  // beyond the range: clamped
  EXPECT_EQ(out[0], 181);  // 0.71 * 255 = 181.05
  EXPECT_EQ(out[1], 5);    // 0.02 * 255 = 5.1
  EXPECT_EQ(out[2], 38);   // 0.15 * 255 = 38.25
  // Sequential map on [0, 4]: a quarter of the way is its second stop.
  curvature_colour(CurvatureQuantity::Absolute, 0, 4, 1.0f, 0, out);
  EXPECT_EQ(out[0], 59);   // 0.230 * 255 = 58.65
  EXPECT_EQ(out[1], 82);   // 0.322 * 255 = 82.11
  EXPECT_EQ(out[2], 139);  // 0.546 * 255 = 139.23
  // A vertex without a fit is mid grey whatever its value.
  curvature_colour(CurvatureQuantity::Absolute, 0, 4, 1.0f, kCurvatureFailed, out);
  EXPECT_EQ(out[0], 128);
  EXPECT_EQ(out[1], 128);
  EXPECT_EQ(out[2], 128);
}

// A value that is not a number (which the fits never give, but a caller's
// array may hold) is grey, never an index into the map.
TEST(CurvatureColours, ValuesThatAreNotNumbersAreGrey) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  VertexCurvature c;
  c.mean = {nan, inf, -inf, 0.5f, 1.0f, nan, 0.25f, -inf, 0.0f};
  c.flags.assign(c.mean.size(), 0);
  std::vector<uint8_t> colors;
  double lo = 0, hi = 0;
  curvature_colours(c, CurvatureQuantity::Mean, colors, &lo, &hi);
  EXPECT_TRUE(std::isfinite(lo) && std::isfinite(hi));
  for (size_t v = 0; v < c.mean.size(); ++v) {
    SCOPED_TRACE(v);
    uint8_t one[4];
    curvature_colour(CurvatureQuantity::Mean, lo, hi, c.mean[v], 0, one);
    EXPECT_EQ(std::vector<uint8_t>(one, one + 4), std::vector<uint8_t>(&colors[4 * v], &colors[4 * v + 4]));
    if (!std::isfinite(c.mean[v])) {
      EXPECT_EQ(one[0], 128);
    }
  }
  uint8_t one[4];
  curvature_colour(CurvatureQuantity::Absolute, nan, nan, 1.0f, 0, one);
  EXPECT_EQ(one[0], 128);
}
