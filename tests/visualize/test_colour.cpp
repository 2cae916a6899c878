// The colour maps as data and the colour-index map of Section 2.2.
#include <gtest/gtest.h>

#include "libcore/errors.h"
#include "libcore/visualize/colour_scale.h"

namespace isoform::visualize {
namespace {

TEST(ColourMap, ControlsAreHitExactlyAndInterpolatedBetween) {
  const ColourMap& v = colour_map(MapId::Viridis);
  EXPECT_EQ(v.at(0.0), (Rgb{68, 1, 84}));
  EXPECT_EQ(v.at(1.0), (Rgb{253, 231, 37}));
  EXPECT_EQ(v.at(0.5), (Rgb{38, 130, 142}));
  // Half way between the first two controls: (70, 20.5, 102), rounded.
  EXPECT_EQ(v.at(1.0 / 16.0), (Rgb{70, 21, 102}));
  EXPECT_EQ(v.at(-3.0), v.at(0.0));
  EXPECT_EQ(v.at(7.0), v.at(1.0));
}

TEST(ColourMap, DivergingIsWhiteInTheMiddleAndGreenWhiteGoesGreenToWhite) {
  EXPECT_EQ(colour_map(MapId::Diverging).at(0.5), (Rgb{255, 255, 255}));
  const ColourMap& g = colour_map(MapId::GreenWhite);
  EXPECT_EQ(g.at(0.0), (Rgb{0, 128, 0}));
  EXPECT_EQ(g.at(1.0), (Rgb{255, 255, 255}));
  EXPECT_EQ(g.at(0.5), (Rgb{128, 192, 128}));
}

TEST(ColourScale, TheSeedsCeilingFormula) {
  ColourScale s;
  s.f_min = -1.0;
  s.f_max = 3.0;
  s.levels = 256;  // c_max = 255
  EXPECT_EQ(s.index(-1.0), 0);
  EXPECT_EQ(s.index(3.0), 255);
  // f = 1: c = 0.5 * 255 = 127.5, ceil 128.
  EXPECT_EQ(s.index(1.0), 128);
  // f on an index: -1 + 4 * 10 / 255 gives c = 10 exactly, not 11.
  EXPECT_EQ(s.index(-1.0 + 40.0 / 255.0), 10);
  // Just above it: 11.
  EXPECT_EQ(s.index(-1.0 + 40.0 / 255.0 + 1e-4), 11);
  // Outside the range the index is clamped.
  EXPECT_EQ(s.index(-9.0), 0);
  EXPECT_EQ(s.index(9.0), 255);
  s.f_max = s.f_min;
  EXPECT_EQ(s.index(5.0), 0);
}

TEST(ColourScale, RangeFromValuesFixedOrSymmetric) {
  ColourSettings c;
  ColourScale s = make_scale(c, {2.0, -0.5, 1.0});
  EXPECT_EQ(s.f_min, -0.5);
  EXPECT_EQ(s.f_max, 2.0);
  c.map = MapId::Diverging;
  s = make_scale(c, {2.0, -0.5, 1.0});
  EXPECT_EQ(s.f_min, -2.0);
  EXPECT_EQ(s.f_max, 2.0);
  // With 256 levels zero gets index ceil(127.5) = 128, a hair past white;
  // with an odd count (c_max even) it is the white middle exactly.
  EXPECT_EQ(s.colour(0.0), (Rgb{255, 255, 254}));
  c.levels = 255;
  EXPECT_EQ(make_scale(c, {2.0, -0.5}).colour(0.0), (Rgb{255, 255, 255}));
  c.fixed_range = true;
  c.range_min = 10;
  c.range_max = 20;
  s = make_scale(c, {2.0});
  EXPECT_EQ(s.f_min, 10.0);
  EXPECT_EQ(s.f_max, 20.0);
  c.range_max = 10;
  EXPECT_THROW(make_scale(c, {}), InvalidArgument);
  c.fixed_range = false;
  c.levels = 1;
  EXPECT_THROW(make_scale(c, {}), InvalidArgument);
}

}  // namespace
}  // namespace isoform::visualize
