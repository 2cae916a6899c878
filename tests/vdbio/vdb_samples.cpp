// Small OpenVDB files of every kind (see vdb_samples.h).
#include "vdb_samples.h"

#include <openvdb/io/File.h>
#include <openvdb/math/Maps.h>
#include <openvdb/tools/LevelSetSphere.h>

namespace isoform::vdbio::test {

namespace {

// A tree with a root tile, an upper-node tile, a lower-node tile, whole
// leaves, and leaves whose inactive voxels hold the background, its
// negative, and other values (so that every mask-compression flag occurs).
template <class GridT>
typename GridT::Ptr filled(const std::string& name, typename GridT::ValueType on,
                           typename GridT::ValueType off) {
  using V = typename GridT::ValueType;
  auto grid = GridT::create(V(off));
  grid->setName(name);
  auto& tree = grid->tree();
  tree.addTile(3, openvdb::Coord(4096, 0, 0), on, true);      // a root tile
  tree.addTile(2, openvdb::Coord(0, 0, 512), on, true);       // in an upper node
  tree.addTile(1, openvdb::Coord(0, 0, 0), on, false);        // in a lower node, inactive
  for (int i = 8; i < 40; ++i)
    for (int j = 0; j < 12; ++j) tree.setValue(openvdb::Coord(i, j, 3 * j % 11), on);
  tree.setValueOff(openvdb::Coord(9, 1, 1), V(on));            // an inactive value of its own
  tree.setValueOff(openvdb::Coord(17, 2, 2), V(off));
  return grid;
}

openvdb::FloatGrid::Ptr sphere(const std::string& name, bool half) {
  auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(2.0f, openvdb::Vec3f(0.25f), 0.1f);
  grid->setName(name);
  grid->setSaveFloatAsHalf(half);
  grid->tree().setValueOff(openvdb::Coord(0, 0, 0), 0.125f);  // a third inactive value
  return grid;
}

openvdb::FloatGrid::Ptr with_map(const std::string& name, openvdb::math::MapBase::Ptr map) {
  auto grid = filled<openvdb::FloatGrid>(name, 2.0f, 0.0f);
  grid->setTransform(std::make_shared<openvdb::math::Transform>(map));
  return grid;
}

}  // namespace

std::vector<VdbSample> vdb_samples() {
  openvdb::initialize();
  namespace m = openvdb::math;
  std::vector<VdbSample> s;
  s.push_back({"float", {filled<openvdb::FloatGrid>("density", 1.5f, 0.0f)}});
  s.push_back({"double", {filled<openvdb::DoubleGrid>("d", 2.5, -1.0)}});
  s.push_back({"int32", {filled<openvdb::Int32Grid>("labels", 7, 0)}});
  s.push_back({"int64", {filled<openvdb::Int64Grid>("ids", 1LL << 40, 3)}});
  s.push_back({"bool", {filled<openvdb::BoolGrid>("flags", true, false)}});
  s.push_back({"mask", {filled<openvdb::MaskGrid>("mask", true, false)}});
  s.push_back({"vec3s", {filled<openvdb::Vec3SGrid>("vel", openvdb::Vec3s(1, 2, 3), openvdb::Vec3s(0.5f))}});
  s.push_back({"vec3d", {filled<openvdb::Vec3DGrid>("veld", openvdb::Vec3d(1, -2, 3), openvdb::Vec3d(0))}});
  s.push_back({"vec3i", {filled<openvdb::Vec3IGrid>("veli", openvdb::Vec3i(1, 2, 3), openvdb::Vec3i(0))}});
  s.push_back({"level set", {sphere("ls", false)}});
  s.push_back({"half", {sphere("ls_half", true)}});
  auto half_vec = filled<openvdb::Vec3SGrid>("vel_half", openvdb::Vec3s(1, 2, 3), openvdb::Vec3s(0));
  half_vec->setSaveFloatAsHalf(true);
  s.push_back({"half vec3s", {half_vec}});
  s.push_back({"empty", {openvdb::FloatGrid::create(0.0f)}});
  s.push_back({"maps",
               {with_map("uniform", std::make_shared<m::UniformScaleMap>(0.5)),
                with_map("scale", std::make_shared<m::ScaleMap>(m::Vec3d(0.5, 1, 2))),
                with_map("translate", std::make_shared<m::TranslationMap>(m::Vec3d(1, 2, 3))),
                with_map("scale translate",
                         std::make_shared<m::ScaleTranslateMap>(m::Vec3d(1, 2, 3), m::Vec3d(4, 5, 6))),
                with_map("uniform translate", std::make_shared<m::UniformScaleTranslateMap>(2.0, m::Vec3d(1))),
                with_map("unitary", std::make_shared<m::UnitaryMap>(m::Vec3d(0, 0, 1), 0.5)),
                with_map("affine", std::make_shared<m::AffineMap>(m::Mat4d(1.0, 0.2, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 2.0,
                                                                              0.0, 1.0, 2.0, 3.0, 1.0))),
                with_map("frustum", std::make_shared<m::NonlinearFrustumMap>(
                                        openvdb::BBoxd(m::Vec3d(0), m::Vec3d(63)), 0.5, 2.0))}});
  auto first = filled<openvdb::FloatGrid>("twice", 1.0f, 0.0f);
  auto second = filled<openvdb::FloatGrid>("twice", 3.0f, 0.0f);
  s.push_back({"repeated name", {first, second}});
  auto shared = first->copyGrid();  // shares the tree: written as an instance
  shared->setName("instance");
  s.push_back({"instance", {first, shared}});
  return s;
}

std::vector<uint32_t> vdb_compressions() {
  using namespace openvdb::io;
  return {COMPRESS_NONE, COMPRESS_ZIP, COMPRESS_ZIP | COMPRESS_ACTIVE_MASK, COMPRESS_BLOSC,
          COMPRESS_BLOSC | COMPRESS_ACTIVE_MASK};
}

void write_vdb_sample(const VdbSample& sample, uint32_t compression, const std::string& path) {
  openvdb::io::File file(path);
  file.setCompression(compression);
  file.write(sample.grids);
  file.close();
}

}  // namespace isoform::vdbio::test
