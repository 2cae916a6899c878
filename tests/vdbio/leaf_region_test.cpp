// LeafBricks::fill_region: a dense box read from the tree, with the values
// that bricks do not hold (inside a level set's inactive interior tiles,
// the background outside), agreeing with the bricks where they do.
#include <gtest/gtest.h>

#include <vector>

#include "test_support.h"
#include "vdbio/leaf_bricks.h"
#include "vdbio/vdb_file.h"

namespace isoform::vdbio {
namespace {

using test::data_file;

openvdb::FloatGrid::Ptr sphere_grid() {
  const auto file = open_vdb(data_file("sphere.vdb"));
  return openvdb::gridPtrCast<openvdb::FloatGrid>(dynamic_cast<const VdbFile&>(*file).read_grid(0));
}

TEST(LeafRegionRealData, SphereInsideOutsideAndBand) {
  const LeafBricks bricks(sphere_grid());
  std::vector<float> out;
  // A row through the centre along x, from outside the band to the middle.
  bricks.fill_region({-70, 0, 0}, {71, 1, 1}, 99.0f, out);
  ASSERT_EQ(out.size(), 71u);
  EXPECT_NEAR(out[0], 0.15f, 1e-3);    // x = -70: outside, the background (half floats)
  EXPECT_NEAR(out[70], -0.15f, 1e-3);  // x = 0: the inactive interior tile
  const auto access = bricks.grid()->getConstAccessor();
  for (int i = 0; i < 71; ++i) EXPECT_EQ(out[size_t(i)], access.getValue(openvdb::Coord(i - 70, 0, 0)));
}

TEST(LeafRegionRealData, AgreesWithTheDefaultWhereBricksHoldSamples) {
  const LeafBricks bricks(sphere_grid());
  // The default gathers bricks; compare it on a box of the narrow band.
  const Index3 lo{50, -6, -6}, dims{12, 12, 12};
  std::vector<float> direct, gathered;
  bricks.fill_region(lo, dims, 0.0f, direct);
  bricks.BrickSource::fill_region(lo, dims, 1234.0f, gathered);
  ASSERT_EQ(direct.size(), gathered.size());
  size_t held = 0;
  for (size_t i = 0; i < direct.size(); ++i) {
    if (gathered[i] == 1234.0f) continue;
    ++held;
    EXPECT_EQ(direct[i], gathered[i]) << i;
  }
  EXPECT_GT(held, direct.size() / 2);
}

}  // namespace
}  // namespace isoform::vdbio
