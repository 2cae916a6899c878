// Bricks over OpenVDB trees: every sample is the tree's value, and every
// cell that crosses the isovalue lies in some brick.
#include "vdbio/leaf_bricks.h"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <set>
#include <vector>

#include "test_support.h"
#include "vdbio/vdb_file.h"

namespace isoform::vdbio {
namespace {

using openvdb::Coord;
using test::data_file;

openvdb::FloatGrid::Ptr read_float_grid(const std::string& name) {
  const auto file = open_vdb(data_file(name));
  return openvdb::gridPtrCast<openvdb::FloatGrid>(dynamic_cast<const VdbFile&>(*file).read_grid(0));
}

// Every brick: aligned 16^3 cells, all samples defined and equal to the
// tree's value at their index, from origin - 1 to origin + 17.
void expect_samples_match_tree(const LeafBricks& bricks) {
  const auto access = bricks.grid()->getConstAccessor();
  Brick brick;
  size_t mismatches = 0;
  for (size_t b = 0; b < bricks.brick_count(); ++b) {
    bricks.fill(b, brick);
    ASSERT_EQ(brick.cells, (Index3{16, 16, 16}));
    ASSERT_TRUE(brick.defined.empty());
    ASSERT_EQ(brick.samples.size(), 19u * 19u * 19u);
    for (int a = 0; a < 3; ++a) ASSERT_EQ(brick.origin[a] % 16, 0);
    for (int k = -1; k <= 17; ++k)
      for (int j = -1; j <= 17; ++j)
        for (int i = -1; i <= 17; ++i) {
          const Coord at(brick.origin[0] + i, brick.origin[1] + j, brick.origin[2] + k);
          mismatches += brick.value(i, j, k) != access.getValue(at);
        }
  }
  EXPECT_EQ(mismatches, 0u);
}

// Every cell (lower corner c) in the active bounding box grown by one whose
// corners reach the isovalue from both sides lies in a brick; bricks are
// aligned, so the brick holding c starts at c rounded down to 16.
void expect_crossings_covered(const LeafBricks& bricks, float iso) {
  const std::set<Coord> origins(bricks.origins().begin(), bricks.origins().end());
  openvdb::CoordBBox box = bricks.grid()->evalActiveVoxelBoundingBox();
  box.expand(1);
  // The box's values copied once, x fastest, so each corner is one load.
  const Coord dims = box.dim();
  std::vector<float> values(box.volume());
  const auto access = bricks.grid()->getConstAccessor();
  size_t n = 0;
  for (int z = box.min().z(); z <= box.max().z(); ++z)
    for (int y = box.min().y(); y <= box.max().y(); ++y)
      for (int x = box.min().x(); x <= box.max().x(); ++x)
        values[n++] = access.getValue(Coord(x, y, z));
  const size_t sy = size_t(dims.x()), sz = sy * size_t(dims.y());
  size_t crossings = 0, missed = 0;
  for (int k = 0; k + 1 < dims.z(); ++k)
    for (int j = 0; j + 1 < dims.y(); ++j)
      for (int i = 0; i + 1 < dims.x(); ++i) {
        const size_t at = size_t(k) * sz + size_t(j) * sy + size_t(i);
        float lo = values[at], hi = lo;
        for (size_t corner : {size_t(1), sy, sy + 1, sz, sz + 1, sz + sy, sz + sy + 1}) {
          lo = std::min(lo, values[at + corner]);
          hi = std::max(hi, values[at + corner]);
        }
        if (lo > iso || hi < iso) continue;
        ++crossings;
        const Coord c = box.min().offsetBy(i, j, k);
        missed += !origins.count(Coord(c.x() & ~15, c.y() & ~15, c.z() & ~15));
      }
  EXPECT_GT(crossings, 0u);
  EXPECT_EQ(missed, 0u) << "of " << crossings << " crossing cells";
}

// may_cross is false only for bricks whose corner samples (0 .. 16 on each
// axis) all lie on one side of iso; returns how many bricks it rules out.
size_t expect_may_cross_keeps_crossings(const LeafBricks& bricks, double iso) {
  Brick brick;
  size_t ruled_out = 0, wrong = 0;
  for (size_t b = 0; b < bricks.brick_count(); ++b) {
    bricks.fill(b, brick);
    bool above = false, below = false;
    for (int k = 0; k <= 16; ++k)
      for (int j = 0; j <= 16; ++j)
        for (int i = 0; i <= 16; ++i) (double(brick.value(i, j, k)) >= iso ? above : below) = true;
    if (bricks.may_cross(b, iso)) continue;
    ++ruled_out;
    wrong += above && below;
  }
  EXPECT_EQ(wrong, 0u) << "crossing bricks ruled out at " << iso;
  return ruled_out;
}

TEST(LeafBricksRealData, SphereSamplesAndCoverage) {
  const LeafBricks bricks(read_float_grid("sphere.vdb"));
  std::cout << "sphere.vdb: " << bricks.brick_count() << " bricks for "
            << bricks.grid()->tree().leafCount() << " leaves\n";
  expect_samples_match_tree(bricks);
  expect_crossings_covered(bricks, 0.0f);
}

// The narrow band's leaves reach past the surface on both sides: many
// bricks lie wholly inside or outside and are ruled out before filling.
TEST(LeafBricksRealData, MayCrossRulesOutOnlyBricksThatDoNotCross) {
  const LeafBricks sphere(read_float_grid("sphere.vdb"));
  const size_t out = expect_may_cross_keeps_crossings(sphere, 0.0);
  std::cout << "sphere.vdb: " << out << " of " << sphere.brick_count() << " bricks ruled out at 0\n";
  EXPECT_GT(out, sphere.brick_count() / 10);
  // Beyond the value range every brick is ruled out.
  EXPECT_EQ(expect_may_cross_keeps_crossings(sphere, 1e6), sphere.brick_count());
  const LeafBricks smoke(read_float_grid("smoke.vdb"));
  EXPECT_GT(expect_may_cross_keeps_crossings(smoke, 0.5), 0u);
}

TEST(LeafBricksRealData, SmokeSamplesAndCoverage) {
  const LeafBricks bricks(read_float_grid("smoke.vdb"));
  std::cout << "smoke.vdb: " << bricks.brick_count() << " bricks for "
            << bricks.grid()->tree().leafCount() << " leaves\n";
  expect_samples_match_tree(bricks);
  expect_crossings_covered(bricks, 0.5f);
}

// Filling every brick of cube.vdb (6,812 leaves) on one thread. The bound
// is far above what a release build takes: it only catches a gross
// regression on a loaded machine. A parallel fill must agree.
TEST(LeafBricksRealData, CubeFillTimeAndThreads) {
  const LeafBricks bricks(read_float_grid("cube.vdb"));
  EXPECT_EQ(bricks.grid()->tree().leafCount(), 6812u);
  Brick brick;
  double checksum = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (size_t b = 0; b < bricks.brick_count(); ++b) {
    bricks.fill(b, brick);
    checksum += brick.samples[brick.at(3, 4, 5)];
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::cout << "cube.vdb: " << bricks.brick_count() << " bricks for 6812 leaves, filled in " << ms
            << " ms on one thread\n";
  EXPECT_LT(ms, 1000.0);
  std::vector<float> parallel(bricks.brick_count());
  tbb::parallel_for(size_t(0), bricks.brick_count(), [&](size_t b) {
    Brick local;
    bricks.fill(b, local);
    parallel[b] = local.samples[local.at(3, 4, 5)];
  });
  double parallel_sum = 0.0;
  for (float v : parallel) parallel_sum += v;
  EXPECT_EQ(parallel_sum, checksum);
}

// A fog volume whose interior is an active tile has no leaves at all; its
// boundary must still be found.
TEST(LeafBricks, ActiveTileAlone) {
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->tree().addTile(2, Coord(128, 0, -128), 1.0f, true);  // one 128^3 tile
  ASSERT_EQ(grid->tree().leafCount(), 0u);
  const LeafBricks bricks(grid);
  EXPECT_GT(bricks.brick_count(), 0u);
  expect_samples_match_tree(bricks);
  expect_crossings_covered(bricks, 0.5f);
}

// An unaligned box filled sparsely: tiles of both levels inside (it holds
// the 128^3 block at the origin), leaves at its faces, an inactive tile of another value beside it
// (which adds no bricks), and a lone voxel.
TEST(LeafBricks, TilesLeavesAndBackground) {
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->sparseFill(openvdb::CoordBBox(Coord(5, -3, -2), Coord(260, 130, 140)), 1.0f, true);
  grid->tree().addTile(1, Coord(-16, 0, 0), 0.25f, false);
  grid->tree().setValue(Coord(-21, -10, 3), 3.0f);
  const LeafBricks bricks(grid);
  expect_samples_match_tree(bricks);
  expect_crossings_covered(bricks, 0.5f);
  // Bricks inside the tiles, from tile values alone, and near the lone voxel.
  EXPECT_GT(expect_may_cross_keeps_crossings(bricks, 0.5), 0u);
  expect_may_cross_keeps_crossings(bricks, 2.0);
}

TEST(LeafBricks, NoCandidatesFromInactiveTiles) {
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->tree().addTile(2, Coord(0, 0, 0), 1.0f, false);
  EXPECT_EQ(LeafBricks(grid).brick_count(), 0u);
}

// The leaf's block and the 7 below it, (0 or 8, 8 or 16, 16 or 24), lie
// in the bricks (0, 0 or 16, 16).
TEST(LeafBricks, OneLeafGivesTheBricksOfItsEightBlocks) {
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->tree().setValue(Coord(9, 17, 25), 1.0f);  // in the leaf at (8, 16, 24)
  const LeafBricks bricks(grid);
  ASSERT_EQ(bricks.brick_count(), 2u);
  EXPECT_EQ(bricks.origins().front(), Coord(0, 0, 16));
  EXPECT_EQ(bricks.origins().back(), Coord(0, 16, 16));
  expect_crossings_covered(bricks, 0.5f);
}

// A leaf at a brick's lower corner: its lower blocks lie in the 7 bricks
// below, every one of which holds one.
TEST(LeafBricks, LeafAtABricksCornerGivesEightBricks) {
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->tree().setValue(Coord(17, 33, -15), 1.0f);  // in the leaf at (16, 32, -16)
  const LeafBricks bricks(grid);
  ASSERT_EQ(bricks.brick_count(), 8u);
  EXPECT_EQ(bricks.origins().front(), Coord(0, 16, -32));
  EXPECT_EQ(bricks.origins().back(), Coord(16, 32, -16));
  expect_samples_match_tree(bricks);
  expect_crossings_covered(bricks, 0.5f);
}

}  // namespace
}  // namespace isoform::vdbio
