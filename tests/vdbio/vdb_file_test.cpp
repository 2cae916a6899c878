// OpenVDB files as VolumeFiles: facts, loading, transforms and every way a
// file can be wrong.
#include "vdbio/vdb_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "libcore/errors.h"
#include "test_support.h"
#include "vdbio/leaf_bricks.h"
#include "vdbio/vdb_convert.h"

namespace isoform::vdbio {
namespace {

using test::data_file;
using test::error_of;
using test::TempDir;
using test::write_grids;

const VdbFile& as_vdb(const std::shared_ptr<VolumeFile>& file) {
  return dynamic_cast<const VdbFile&>(*file);
}

// Affine and OpenVDB's transform agree on a few index points.
void expect_same_map(const Affine& affine, const openvdb::math::Transform& transform) {
  for (const openvdb::Vec3d p :
       {openvdb::Vec3d(0, 0, 0), openvdb::Vec3d(3, -7, 11), openvdb::Vec3d(-40, 25, 60)}) {
    const openvdb::Vec3d expected = transform.indexToWorld(p);
    const Vec3d got = affine.apply({p.x(), p.y(), p.z()});
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(got[a], expected[a], 1e-9) << "axis " << a;
  }
}

TEST(VdbFileRealData, SphereFacts) {
  const auto file = open_vdb(data_file("sphere.vdb"));
  ASSERT_EQ(file->grid_count(), 1);
  const GridFacts f = file->facts(0);
  EXPECT_EQ(f.name, "ls_sphere");
  EXPECT_EQ(f.value_type, "half");
  EXPECT_EQ(f.grid_class, GridClass::LevelSet);
  EXPECT_TRUE(f.is_scalar);
  EXPECT_EQ(f.active_voxels, 270638);
  EXPECT_EQ(f.bbox_min, (Index3{-62, -62, -62}));
  EXPECT_EQ(f.bbox_max, (Index3{62, 62, 62}));
  EXPECT_NEAR(f.background, 0.15, 1e-4);
  EXPECT_LT(f.value_min, 0.0);
  EXPECT_GT(f.value_max, 0.0);
  EXPECT_GE(f.value_min, -f.background - 1e-6);
  EXPECT_LE(f.value_max, f.background + 1e-6);
  // Voxel size 0.05 along each axis (stored as a 32-bit float), no translation.
  const Vec3d size = f.index_to_world.voxel_size();
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(size[a], 0.05, 1e-8);
  const Vec3d p = f.index_to_world.apply({20, -10, 4});
  EXPECT_NEAR(p[0], 1.0, 1e-7);
  EXPECT_NEAR(p[1], -0.5, 1e-7);
  EXPECT_NEAR(p[2], 0.2, 1e-7);
}

TEST(VdbFileRealData, SmokeTransformHasTranslation) {
  const auto file = open_vdb(data_file("smoke.vdb"));
  const GridFacts f = file->facts(0);
  EXPECT_EQ(f.grid_class, GridClass::Fog);
  EXPECT_EQ(f.active_voxels, 1049275);
  EXPECT_EQ(f.background, 0.0);
  EXPECT_GT(f.value_min, 0.0);
  EXPECT_NEAR(f.value_max, 5.71, 0.01);
  EXPECT_EQ(f.bbox_min, (Index3{1, 2, 1}));
  EXPECT_EQ(f.bbox_max, (Index3{111, 223, 112}));
  EXPECT_NEAR(f.index_to_world.m[0][3], -34.0476, 1e-4);
  expect_same_map(f.index_to_world, as_vdb(file).read_grid(0)->transform());
}

TEST(VdbFileRealData, LoadSphere) {
  const auto file = open_vdb(data_file("sphere.vdb"));
  const auto grid = file->load(0);
  EXPECT_EQ(grid->name, "ls_sphere");
  EXPECT_EQ(grid->grid_class, GridClass::LevelSet);
  EXPECT_NEAR(grid->background, 0.15, 1e-4);
  const GridFacts f = file->facts(0);
  EXPECT_EQ(grid->value_min, f.value_min);
  EXPECT_EQ(grid->value_max, f.value_max);
  const auto* bricks = dynamic_cast<const LeafBricks*>(grid->bricks.get());
  ASSERT_NE(bricks, nullptr);
  // A brick holds 2^3 leaf blocks: at least one brick per 8 leaves, and the
  // blocks below the narrow band's leaves add bricks beyond those.
  EXPECT_GT(8 * bricks->brick_count(), bricks->grid()->tree().leafCount());
}

// A rotation, non-uniform scale and translation: a transposed matrix or a
// translation from the wrong row would show.
TEST(VdbConvert, AffineFollowsOpenVdbRowVectors) {
  openvdb::Mat4d m = openvdb::Mat4d::identity();
  m.preScale(openvdb::Vec3d(0.5, 2.0, 1.5));
  m.postRotate(openvdb::math::Z_AXIS, 0.3);
  m.postRotate(openvdb::math::X_AXIS, -0.7);
  m.postTranslate(openvdb::Vec3d(4.0, -2.0, 9.0));
  const auto transform = openvdb::math::Transform::createLinearTransform(m);
  const Affine affine = to_affine(*transform, "test");
  expect_same_map(affine, *transform);
  expect_same_map(affine, *to_transform(affine));
}

TEST(VdbFile, MissingFile) {
  TempDir dir;
  const std::string path = dir.file("nothing.vdb");
  EXPECT_EQ(error_of<IoError>([&] { open_vdb(path); }), path + ": no such file");
}

TEST(VdbFile, NotAVdbFile) {
  TempDir dir;
  const std::string path = dir.file("text.vdb");
  std::ofstream(path) << "this is not a volume\n";
  EXPECT_EQ(error_of<FormatError>([&] { open_vdb(path); }), path + ": not an OpenVDB file");
}

// The first 60% of a file: OpenVDB itself would read it without complaint.
void copy_prefix(const std::string& from, const std::string& to, double fraction) {
  std::filesystem::copy_file(from, to);
  std::filesystem::resize_file(to,
                               std::uintmax_t(fraction * double(std::filesystem::file_size(to))));
}

TEST(VdbFileRealData, TruncatedAtOpen) {
  TempDir dir;
  const std::string path = dir.file("sphere60.vdb");
  copy_prefix(data_file("sphere.vdb"), path, 0.6);
  const std::string message = error_of<FormatError>([&] { open_vdb(path); });
  EXPECT_EQ(message.rfind(path + ": truncated or damaged OpenVDB file (", 0), 0u) << message;
}

TEST(VdbFileRealData, TruncatedAfterOpenFailsAtLoad) {
  TempDir dir;
  const std::string path = dir.file("sphere.vdb");
  std::filesystem::copy_file(data_file("sphere.vdb"), path);
  const auto file = open_vdb(path);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) * 6 / 10);
  const std::string message = error_of<FormatError>([&] { file->load(0); });
  EXPECT_EQ(message.rfind(path + ": truncated or damaged OpenVDB file (", 0), 0u) << message;
}

TEST(VdbFileRealData, DescribingThenLoadingReadsTheGridOnce) {
  // The grid read for facts() is the one load() contours: cutting the file
  // in between no longer matters, and the loaded grid has the facts' range.
  TempDir dir;
  const std::string path = dir.file("sphere.vdb");
  std::filesystem::copy_file(data_file("sphere.vdb"), path);
  const auto file = open_vdb(path);
  const GridFacts facts = file->facts(0);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) * 6 / 10);
  const auto grid = file->load(0);
  ASSERT_TRUE(grid && grid->bricks);
  EXPECT_GT(grid->bricks->brick_count(), 0u);
  EXPECT_EQ(grid->value_min, facts.value_min);
  EXPECT_EQ(grid->value_max, facts.value_max);
  // Loading again reads the file again, which is now cut short.
  EXPECT_NE(error_of<FormatError>([&] { file->load(0); }).find("truncated"), std::string::npos);
}

TEST(VdbFile, CutInsideTheHeader) {
  TempDir dir;
  const std::string path = dir.file("short.vdb");
  copy_prefix(data_file("sphere.vdb"), path, 100.0 / 829636.0);
  EXPECT_NE(error_of<FormatError>([&] { open_vdb(path); }).find("truncated"), std::string::npos);
}

openvdb::FloatGrid::Ptr float_grid(const std::string& name, float background) {
  auto grid = openvdb::FloatGrid::create(background);
  grid->setName(name);
  return grid;
}

TEST(VdbFile, VectorGridIsUnsupported) {
  TempDir dir;
  const std::string path = dir.file("vel.vdb");
  auto vel = openvdb::Vec3SGrid::create();
  vel->setName("vel");
  vel->tree().setValue(openvdb::Coord(1, 2, 3), openvdb::Vec3s(1, 0, 0));
  write_grids(path, {vel});
  const auto file = open_vdb(path);
  const GridFacts f = file->facts(0);
  EXPECT_EQ(f.value_type, "vec3s");
  EXPECT_FALSE(f.is_scalar);
  EXPECT_EQ(f.active_voxels, 1);
  EXPECT_EQ(error_of<Unsupported>([&] { file->load(0); }),
            path + ": grid 'vel' is a vec3s grid; isoform contours scalar grids only");
}

TEST(VdbFile, EmptyGrid) {
  TempDir dir;
  const std::string path = dir.file("empty.vdb");
  write_grids(path, {float_grid("x", 1.0f)});
  const auto file = open_vdb(path);
  EXPECT_EQ(file->facts(0).active_voxels, 0);
  EXPECT_EQ(error_of<FormatError>([&] { file->load(0); }),
            path + ": grid 'x' is empty (no active voxels)");
}

TEST(VdbFile, NanIsRefusedWithItsVoxel) {
  TempDir dir;
  const std::string path = dir.file("nan.vdb");
  auto grid = float_grid("bad", 0.0f);
  grid->tree().setValue(openvdb::Coord(0, 0, 0), 1.0f);
  grid->tree().setValue(openvdb::Coord(5, -6, 7), std::numeric_limits<float>::quiet_NaN());
  write_grids(path, {grid});
  const auto file = open_vdb(path);
  EXPECT_EQ(error_of<FormatError>([&] { file->load(0); }),
            path + ": grid 'bad' has a NaN value at voxel (5, -6, 7); isoform needs finite values");
}

// Many leaves, so that the value scan runs over several ranges at once.
openvdb::FloatGrid::Ptr many_leaves(const std::string& name) {
  auto grid = float_grid(name, 0.0f);
  uint32_t state = 99;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j)
      for (int k = 0; k < 16; ++k) {
        state = state * 1664525u + 1013904223u;
        const float value = float(state >> 8) / float(1 << 24) * 200.0f - 100.0f;
        grid->tree().setValue(openvdb::Coord(8 * i - 60, 8 * j + 3, 8 * k - 1), value);
      }
  return grid;
}

TEST(VdbFile, ScanOfManyLeavesGivesTheRangeAndTheFirstBadValue) {
  TempDir dir;
  // The range: the extremes of the active values, from facts() and from
  // load() with and without facts() before it.
  {
    const std::string path = dir.file("range.vdb");
    auto grid = many_leaves("f");
    float lo = 1e30f, hi = -1e30f;
    for (auto v = grid->cbeginValueOn(); v; ++v) {
      lo = std::min(lo, *v);
      hi = std::max(hi, *v);
    }
    write_grids(path, {grid});
    const auto described = open_vdb(path);
    EXPECT_EQ(described->facts(0).value_min, double(lo));
    EXPECT_EQ(described->facts(0).value_max, double(hi));
    const auto after_facts = described->load(0);
    EXPECT_EQ(after_facts->value_min, double(lo));
    EXPECT_EQ(after_facts->value_max, double(hi));
    const auto alone = open_vdb(path)->load(0);
    EXPECT_EQ(alone->value_min, double(lo));
    EXPECT_EQ(alone->value_max, double(hi));
  }
  // Three bad values in leaves far apart: the one reported is the first in
  // the tree's leaf order, whichever part of the scan meets it.
  const std::string path = dir.file("bad.vdb");
  auto grid = many_leaves("bad");
  const openvdb::Coord bad[3] = {{8 * 13 - 60, 8 * 2 + 3, 8 * 9 - 1}, {8 * 5 - 60, 8 * 11 + 3, 8 * 1 - 1},
                                 {8 * 9 - 60, 8 * 7 + 3, 8 * 14 - 1}};
  for (const auto& c : bad) grid->tree().setValue(c, std::numeric_limits<float>::infinity());
  openvdb::Coord first;
  bool found = false;
  for (auto leaf = grid->tree().cbeginLeaf(); leaf && !found; ++leaf)
    for (openvdb::Index n = 0; n < openvdb::FloatTree::LeafNodeType::SIZE && !found; ++n)
      if (!std::isfinite(leaf->getValue(n))) {
        first = leaf->offsetToGlobalCoord(n);
        found = true;
      }
  ASSERT_TRUE(found);
  write_grids(path, {grid});
  const std::string expected = path + ": grid 'bad' has an infinite value at voxel (" + std::to_string(first.x()) +
                               ", " + std::to_string(first.y()) + ", " + std::to_string(first.z()) +
                               "); isoform needs finite values";
  EXPECT_EQ(error_of<FormatError>([&] { open_vdb(path)->facts(0); }), expected);
  EXPECT_EQ(error_of<FormatError>([&] { open_vdb(path)->load(0); }), expected);
}

TEST(VdbFile, IntegerAndDoubleGridsLoadAsFloat) {
  TempDir dir;
  const std::string path = dir.file("types.vdb");
  auto ints = openvdb::Int32Grid::create(0);
  ints->setName("labels");
  ints->tree().setValue(openvdb::Coord(1, 1, 1), 7);
  ints->tree().setValue(openvdb::Coord(2, 1, 1), -3);
  auto doubles = openvdb::DoubleGrid::create(0.5);
  doubles->setName("field");
  doubles->tree().setValue(openvdb::Coord(-9, 4, 0), 2.25);
  write_grids(path, {ints, doubles});
  const auto file = open_vdb(path);
  ASSERT_EQ(file->grid_count(), 2);
  EXPECT_EQ(file->facts(0).value_type, "int32");
  EXPECT_EQ(file->facts(0).value_min, -3.0);
  EXPECT_EQ(file->facts(0).value_max, 7.0);
  EXPECT_EQ(file->facts(1).value_type, "double");
  const auto field = file->load(1);
  EXPECT_EQ(field->background, 0.5);
  EXPECT_EQ(field->value_min, 2.25);
  const auto* bricks = dynamic_cast<const LeafBricks*>(field->bricks.get());
  ASSERT_NE(bricks, nullptr);
  EXPECT_EQ(bricks->grid()->tree().getValue(openvdb::Coord(-9, 4, 0)), 2.25f);
}

TEST(VdbFile, ActiveTilesCountInFacts) {
  TempDir dir;
  const std::string path = dir.file("tile.vdb");
  auto grid = float_grid("fog", 0.0f);
  grid->tree().addTile(1, openvdb::Coord(0, 0, 0), 2.0f, true);  // one 8^3 tile
  grid->tree().setValue(openvdb::Coord(20, 0, 0), 0.5f);
  write_grids(path, {grid});
  const GridFacts f = open_vdb(path)->facts(0);
  EXPECT_EQ(f.active_voxels, 513);
  EXPECT_EQ(f.value_min, 0.5);
  EXPECT_EQ(f.value_max, 2.0);
  EXPECT_EQ(f.bbox_max, (Index3{20, 7, 7}));
}

TEST(VdbFile, FrustumIsUnsupported) {
  TempDir dir;
  const std::string path = dir.file("frustum.vdb");
  auto grid = float_grid("cone", 0.0f);
  grid->tree().setValue(openvdb::Coord(1, 1, 1), 1.0f);
  grid->setTransform(openvdb::math::Transform::createFrustumTransform(
      openvdb::BBoxd(openvdb::Vec3d(0), openvdb::Vec3d(10)), 0.5, 2.0));
  write_grids(path, {grid});
  const auto file = open_vdb(path);
  const std::string message = error_of<Unsupported>([&] { file->load(0); });
  EXPECT_EQ(message.rfind(path + ": grid 'cone' has a", 0), 0u) << message;
  EXPECT_NE(message.find("affine"), std::string::npos);
}

TEST(VdbFile, GridsOfTheSameNameAreKeptApart) {
  TempDir dir;
  const std::string path = dir.file("twins.vdb");
  auto first = float_grid("density", 0.0f);
  first->tree().setValue(openvdb::Coord(0, 0, 0), 1.0f);
  auto second = float_grid("density", 0.0f);
  second->tree().setValue(openvdb::Coord(0, 0, 0), 2.0f);
  write_grids(path, {first, second});
  const auto file = open_vdb(path);
  ASSERT_EQ(file->grid_count(), 2);
  EXPECT_EQ(file->facts(0).value_max, 1.0);
  EXPECT_EQ(file->facts(1).value_max, 2.0);
  EXPECT_EQ(file->load(1)->name, "density");
}

TEST(VdbFile, GridIndexOutOfRange) {
  TempDir dir;
  const std::string path = dir.file("one.vdb");
  auto grid = float_grid("a", 0.0f);
  grid->tree().setValue(openvdb::Coord(0, 0, 0), 1.0f);
  write_grids(path, {grid});
  const auto file = open_vdb(path);
  EXPECT_THROW(file->load(1), InvalidArgument);
  EXPECT_THROW(file->facts(-1), InvalidArgument);
}

}  // namespace
}  // namespace isoform::vdbio
