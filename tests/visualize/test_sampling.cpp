// Trilinear sampling through the bricks: grid values at grid points, the
// trilinear interpolant between them, and the brick-gathered dense region.
#include <gtest/gtest.h>

#include <cmath>

#include "libcore/errors.h"
#include "visualize_support.h"

namespace isoform::visualize {
namespace {

using test::make_grid;

double wiggle(int i, int j, int k) { return std::sin(1.3 * i) + std::cos(0.7 * j * k) + 0.01 * i * j; }

TEST(Sampling, GridPointsGiveTheSamples) {
  const auto g = make_grid({19, 7, 5}, wiggle);
  const SampleRegion region(*g.grid, g.domain.lo, g.domain.hi);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 19; ++i) {
        EXPECT_EQ(region.at(i, j, k), float(wiggle(i, j, k)));
        EXPECT_DOUBLE_EQ(region.trilinear({double(i), double(j), double(k)}), double(float(wiggle(i, j, k))));
      }
}

TEST(Sampling, BetweenGridPointsItIsTrilinear) {
  const auto g = make_grid({6, 5, 4}, [](int i, int j, int k) { return test::trilinear_field(i, j, k); });
  const SampleRegion region(*g.grid, g.domain.lo, g.domain.hi);
  for (double x : {0.0, 0.3, 2.5, 4.99, 5.0})
    for (double y : {0.1, 1.75, 4.0})
      for (double z : {0.0, 1.2, 2.9, 3.0})
        EXPECT_NEAR(region.trilinear({x, y, z}), test::trilinear_field(x, y, z), 1e-5) << x << " " << y << " " << z;
  // A non-trilinear field: the eight corners' weights by hand at (1.25, 2.5, 0.75).
  const auto w = make_grid({4, 4, 4}, wiggle);
  const SampleRegion r2(*w.grid, w.domain.lo, w.domain.hi);
  double expected = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int i = 1 + (c & 1), j = 2 + ((c >> 1) & 1), k = (c >> 2) & 1;
    const double weight = ((c & 1) ? 0.25 : 0.75) * ((c & 2) ? 0.5 : 0.5) * ((c & 4) ? 0.75 : 0.25);
    expected += weight * double(float(wiggle(i, j, k)));
  }
  EXPECT_NEAR(r2.trilinear({1.25, 2.5, 0.75}), expected, 1e-12);
}

TEST(Sampling, SubRegionFromBricksAndUncoveredSamples) {
  const auto g = make_grid({40, 3, 3}, wiggle);  // three bricks along x
  const SampleRegion region(*g.grid, {14, 1, 0}, {33, 2, 2});
  EXPECT_EQ(region.at(14, 1, 0), float(wiggle(14, 1, 0)));
  EXPECT_EQ(region.at(33, 2, 2), float(wiggle(33, 2, 2)));
  // Past the array no brick defines a sample: the given outside value.
  std::vector<float> out;
  g.grid->bricks->fill_region({38, 0, 0}, {4, 1, 1}, -7.0f, out);
  EXPECT_EQ(out[0], float(wiggle(38, 0, 0)));
  EXPECT_EQ(out[1], float(wiggle(39, 0, 0)));
  EXPECT_EQ(out[2], -7.0f);
  EXPECT_EQ(out[3], -7.0f);
}

TEST(Domain, WorldAndIndexAndOutside) {
  const auto g = make_grid({5, 5, 5}, wiggle, {0.5, 2.0, 1.0}, {-1.0, 3.0, 0.0});
  const Vec3d w = g.domain.world({2, 1, 4});
  EXPECT_DOUBLE_EQ(w[0], 0.0);
  EXPECT_DOUBLE_EQ(w[1], 5.0);
  EXPECT_DOUBLE_EQ(w[2], 4.0);
  const Vec3d back = g.domain.index(w);
  EXPECT_NEAR(back[0], 2, 1e-12);
  EXPECT_NEAR(back[1], 1, 1e-12);
  EXPECT_NEAR(back[2], 4, 1e-12);
  EXPECT_NO_THROW(g.domain.require_inside({4, 0, 4}, "p"));
  EXPECT_THROW(g.domain.require_inside({4.01, 0, 4}, "p"), InvalidArgument);
  EXPECT_THROW(g.domain.require_inside({0, -0.5, 0}, "p"), InvalidArgument);
}

}  // namespace
}  // namespace isoform::visualize
