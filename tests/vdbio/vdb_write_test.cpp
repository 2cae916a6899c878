// Writing volumes as OpenVDB files: values, sparsity, transforms, and a
// target that is never left half written.
#include "vdbio/vdb_write.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "libcore/errors.h"
#include "test_support.h"
#include "vdbio/dense_read.h"
#include "vdbio/vdb_file.h"

namespace isoform::vdbio {
namespace {

using test::data_file;
using test::error_of;
using test::TempDir;

std::shared_ptr<DenseVolume> headsq(const std::string& path) {
  RawLayout layout;
  layout.dims = {64, 64, 93};
  layout.spacing = {3.2, 3.2, 1.5};
  return read_raw(path, layout);
}

openvdb::FloatGrid::Ptr first_float_grid(const std::string& path) {
  const auto file = open_vdb(path);
  return openvdb::gridPtrCast<openvdb::FloatGrid>(dynamic_cast<const VdbFile&>(*file).read_grid(0));
}

TEST(VdbWriteRealData, HeadsqRoundTrip) {
  TempDir dir;
  const auto volume = headsq(data_file("headsq_64x64x93_u16le.raw"));
  const std::string path = dir.file("headsq.vdb");
  write_vdb(*volume, path);
  EXPECT_EQ(dir.entry_count(), 1u);  // no temporary file left beside it

  const auto file = open_vdb(path);
  const GridFacts f = file->facts(0);
  EXPECT_EQ(f.name, "density");
  EXPECT_EQ(f.grid_class, GridClass::Fog);
  EXPECT_EQ(f.value_max, 3926.0);
  EXPECT_LT(f.active_voxels, 64 * 64 * 93);  // zeros are the background
  const Vec3d size = f.index_to_world.voxel_size();
  EXPECT_NEAR(size[0], 3.2, 1e-12);
  EXPECT_NEAR(size[1], 3.2, 1e-12);
  EXPECT_NEAR(size[2], 1.5, 1e-12);

  const auto grid = first_float_grid(path);
  const auto access = grid->getConstAccessor();
  const auto& dense = dynamic_cast<const DenseBricks&>(*volume->load(0)->bricks).values();
  size_t n = 0, mismatches = 0;
  for (int k = 0; k < 93; ++k)
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i)
        mismatches += access.getValue(openvdb::Coord(i, j, k)) != dense[n++];
  EXPECT_EQ(mismatches, 0u);
}

TEST(VdbWriteRealData, VdbRoundTripKeepsTheTree) {
  TempDir dir;
  const auto source = open_vdb(data_file("sphere.vdb"));
  const std::string path = dir.file("copy.vdb");
  write_vdb(*source, path);
  const auto before = first_float_grid(data_file("sphere.vdb"));
  const auto after = first_float_grid(path);
  EXPECT_EQ(after->getName(), "ls_sphere");
  EXPECT_EQ(after->getGridClass(), openvdb::GRID_LEVEL_SET);
  EXPECT_EQ(after->tree().leafCount(), before->tree().leafCount());
  EXPECT_EQ(after->activeVoxelCount(), before->activeVoxelCount());
  EXPECT_EQ(after->background(), before->background());
  EXPECT_TRUE(after->transform() == before->transform());
  size_t mismatches = 0;
  const auto access = after->getConstAccessor();
  for (auto v = before->cbeginValueOn(); v; ++v) mismatches += access.getValue(v.getCoord()) != *v;
  EXPECT_EQ(mismatches, 0u);
}

TEST(VdbWrite, NonScalarGridsAreCopied) {
  TempDir dir;
  const std::string input = dir.file("in.vdb");
  auto vel = openvdb::Vec3SGrid::create();
  vel->setName("vel");
  vel->tree().setValue(openvdb::Coord(1, 2, 3), openvdb::Vec3s(1, 2, 3));
  auto labels = openvdb::Int32Grid::create(0);
  labels->setName("labels");
  labels->tree().setValue(openvdb::Coord(4, 5, 6), 9);
  test::write_grids(input, {vel, labels});
  const std::string output = dir.file("out.vdb");
  write_vdb(*open_vdb(input), output);
  const auto copy = open_vdb(output);
  ASSERT_EQ(copy->grid_count(), 2);
  EXPECT_EQ(copy->facts(0).value_type, "vec3s");
  EXPECT_EQ(copy->facts(1).value_type, "float");
  EXPECT_EQ(copy->facts(1).value_max, 9.0);
}

TEST(VdbWrite, MissingDirectoryLeavesNothing) {
  TempDir dir;
  const auto volume = std::make_shared<DenseVolume>("density", GridClass::Fog,
                                                    std::vector<float>{0, 1, 2, 3, 4, 5, 6, 7},
                                                    Index3{2, 2, 2}, Affine());
  const std::string path = dir.file("missing/out.vdb");
  const std::string message = error_of<IoError>([&] { write_vdb(*volume, path); });
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
  EXPECT_EQ(dir.entry_count(), 0u);
}

// A target that cannot be replaced (a directory): the temporary file is
// removed and the target stays as it was.
TEST(VdbWrite, FailedRenameLeavesNothing) {
  TempDir dir;
  const auto volume = std::make_shared<DenseVolume>("density", GridClass::Fog,
                                                    std::vector<float>{0, 1, 2, 3, 4, 5, 6, 7},
                                                    Index3{2, 2, 2}, Affine());
  const std::string path = dir.file("taken.vdb");
  std::filesystem::create_directory(path);
  const std::string message = error_of<IoError>([&] { write_vdb(*volume, path); });
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
  EXPECT_EQ(dir.entry_count(), 1u);
  EXPECT_TRUE(std::filesystem::is_directory(path));
}

TEST(VdbWriteRealData, RefusesToOverwriteItsSource) {
  TempDir dir;
  const std::string raw = dir.file("headsq.raw");
  std::filesystem::copy_file(data_file("headsq_64x64x93_u16le.raw"), raw);
  const auto volume = headsq(raw);
  EXPECT_THROW(write_vdb(*volume, raw), InvalidArgument);
  EXPECT_THROW(write_vdb(*volume, (dir.path() / "." / "headsq.raw").string()), InvalidArgument);
  EXPECT_EQ(std::filesystem::file_size(raw), 761856u);

  const std::string vdb = dir.file("sphere.vdb");
  std::filesystem::copy_file(data_file("sphere.vdb"), vdb);
  EXPECT_THROW(write_vdb(*open_vdb(vdb), vdb), InvalidArgument);
  EXPECT_EQ(dir.entry_count(), 2u);
}

}  // namespace
}  // namespace isoform::vdbio
