// Curvature results of a sparse VDB (libcore/curvature/graph_volume.h)
// written by vdbio: the written grids' active voxels are exactly the input's,
// even where the result equals the background 0.
#include <gtest/gtest.h>

#include <cstring>

#include "libcore/curvature/graph_volume.h"
#include "libcore/errors.h"
#include "test_support.h"
#include "vdbio/active_bricks.h"
#include "vdbio/vdb_file.h"
#include "vdbio/vdb_write.h"

namespace isoform::vdbio {
namespace {

using test::TempDir;

openvdb::FloatGrid::Ptr read_float_grid(const std::string& path, const std::string& name) {
  openvdb::io::File file(path);
  file.open();
  auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(name));
  file.close();
  return grid;
}

// Two blobs across leaf boundaries, one flat (f = 2, curvature exactly 0)
// and one curved, plus an isolated voxel that no fit can use.
openvdb::FloatGrid::Ptr sparse_input() {
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName("f");
  grid->setTransform(openvdb::math::Transform::createLinearTransform(0.25));
  auto access = grid->getAccessor();
  for (int k = -6; k <= 6; ++k)
    for (int j = -6; j <= 6; ++j)
      for (int i = -6; i <= 6; ++i) {
        if (i * i + j * j + k * k <= 30) access.setValueOn(openvdb::Coord(i, j, k), 2.0f);
        if ((i - 1) * (i - 1) + j * j + k * k <= 25)
          access.setValueOn(openvdb::Coord(i + 20, j, k), float(0.01 * (i * i - j * j + 3 * k)));
      }
  access.setValueOn(openvdb::Coord(40, 40, 40), 1.0f);
  return grid;
}

TEST(GraphCurvatureWrite, ResultGridsKeepTheInputsActiveVoxels) {
  TempDir dir;
  const std::string in = dir.file("in.vdb"), out = dir.file("curv.vdb");
  const auto input = sparse_input();
  test::write_grids(in, {input});
  const auto file = open_vdb(in);
  const auto grid = file->load(0);
  ASSERT_TRUE(grid->active_bricks);
  const auto result = graph_curvature_volume(*grid, file->path(), GraphVolumeOptions{}, Progress(nullptr));
  EXPECT_EQ(result->stats().points, static_cast<long long>(input->activeVoxelCount()));
  // The isolated voxel, and the blobs' poles, have no fit.
  EXPECT_GE(result->stats().fits[size_t(GraphFit::None)], 1);
  write_vdb(*result, out);
  for (const char* name : {"mean", "gauss", "k1", "k2", "k3"}) {
    const auto written = read_float_grid(out, name);
    ASSERT_TRUE(written) << name;
    EXPECT_TRUE(written->tree().hasSameTopology(input->tree())) << name;
    EXPECT_EQ(written->activeVoxelCount(), input->activeVoxelCount()) << name;
    EXPECT_EQ(written->getGridClass(), openvdb::GRID_UNKNOWN) << name;
    // The flat blob's curvature is exactly 0, the background, and active.
    EXPECT_TRUE(written->tree().isValueOn(openvdb::Coord(0, 0, 0))) << name;
    EXPECT_EQ(written->tree().getValue(openvdb::Coord(0, 0, 0)), 0.0f) << name;
    EXPECT_TRUE(written->tree().isValueOn(openvdb::Coord(40, 40, 40))) << name;
    EXPECT_EQ(written->tree().getValue(openvdb::Coord(40, 40, 40)), 0.0f) << name;
  }
  // The curved blob: f = 0.01 ((I - 20)^2 - j^2 + 3k) at index (I, j, k) on
  // voxels of 0.25 is 0.16 (x - 5)^2 - 0.16 y^2 + 0.12 z in world units. At
  // its centre, index (21, 0, 0), the gradient is (0.08, 0, 0.12): 4.36 there.
  const auto k1 = read_float_grid(out, "k1");
  const Sym3 hess = {{{0.32, 0, 0}, {0, -0.32, 0}, {0, 0, 0}}};
  const GraphPrincipal exact = graph_principal_from_derivatives({0.08, 0.0, 0.12}, hess);
  EXPECT_NEAR(k1->tree().getValue(openvdb::Coord(21, 0, 0)), exact.k1, 1e-4);
  // The result remembers its source: writing over it is refused.
  EXPECT_THROW(write_vdb(*result, in), InvalidArgument);
}

TEST(GraphCurvatureWrite, SameBitsOnOneAndTwoThreads) {
  TempDir dir;
  const std::string in = dir.file("in.vdb");
  test::write_grids(in, {sparse_input()});
  const auto grid = open_vdb(in)->load(0);
  std::vector<std::vector<float>> runs;
  for (int threads : {1, 2}) {
    GraphVolumeOptions o;
    o.threads = threads;
    const auto result = graph_curvature_volume(*grid, in, o, Progress(nullptr));
    std::vector<float> all;
    Brick brick;
    for (int g = 0; g < kGraphGrids; ++g) {
      const auto r = result->load(g);
      for (size_t b = 0; b < r->bricks->brick_count(); ++b) {
        r->bricks->fill(b, brick);
        all.insert(all.end(), brick.samples.begin(), brick.samples.end());
      }
    }
    runs.push_back(all);
  }
  ASSERT_EQ(runs[0].size(), runs[1].size());
  EXPECT_EQ(std::memcmp(runs[0].data(), runs[1].data(), runs[0].size() * sizeof(float)), 0);
}

TEST(GraphCurvatureWrite, ActiveBricksMarkActiveVoxelsAsDefined) {
  const auto input = sparse_input();
  const ActiveBricks bricks(input);
  Brick brick;
  long long own_defined = 0;
  for (size_t b = 0; b < bricks.brick_count(); ++b) {
    bricks.fill(b, brick);
    for (int k = -1; k <= 9; ++k)
      for (int j = -1; j <= 9; ++j)
        for (int i = -1; i <= 9; ++i) {
          const openvdb::Coord p(brick.origin[0] + i, brick.origin[1] + j, brick.origin[2] + k);
          ASSERT_EQ(brick.is_defined(i, j, k), input->tree().isValueOn(p));
          const bool own = i >= 0 && j >= 0 && k >= 0 && i < 8 && j < 8 && k < 8;
          own_defined += own && brick.is_defined(i, j, k);
        }
  }
  EXPECT_EQ(own_defined, static_cast<long long>(input->activeVoxelCount()));
}

}  // namespace
}  // namespace isoform::vdbio
