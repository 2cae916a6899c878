// Conversions between OpenVDB's grid vocabulary and libcore's.
#include "vdb_convert.h"

#include <mutex>

#include "libcore/errors.h"

namespace isoform::vdbio {

void initialize_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

Affine to_affine(const openvdb::math::Transform& transform, const std::string& what) {
  if (!transform.isLinear())
    throw Unsupported(what + " has a " + transform.mapType() +
                      " transform; isoform handles affine index-to-world maps only");
  const openvdb::Mat4d vdb = transform.baseMap()->getAffineMap()->getMat4();
  // Row-vector M to column-vector m: m[r][c] = M(c, r), translation from row 3.
  Affine affine;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) affine.m[r][c] = vdb(c, r);
    affine.m[r][3] = vdb(3, r);
  }
  return affine;
}

openvdb::math::Transform::Ptr to_transform(const Affine& affine) {
  if (affine.determinant() == 0.0)
    throw InvalidArgument("the index-to-world transform is singular");
  openvdb::Mat4d vdb = openvdb::Mat4d::identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) vdb(c, r) = affine.m[r][c];
    vdb(3, r) = affine.m[r][3];
  }
  return openvdb::math::Transform::createLinearTransform(vdb);
}

GridClass to_grid_class(openvdb::GridClass grid_class) {
  switch (grid_class) {
    case openvdb::GRID_LEVEL_SET:
      return GridClass::LevelSet;
    case openvdb::GRID_FOG_VOLUME:
      return GridClass::Fog;
    default:
      return GridClass::Other;
  }
}

openvdb::GridClass to_vdb_class(GridClass grid_class) {
  switch (grid_class) {
    case GridClass::LevelSet:
      return openvdb::GRID_LEVEL_SET;
    case GridClass::Fog:
      return openvdb::GRID_FOG_VOLUME;
    default:
      return openvdb::GRID_UNKNOWN;
  }
}

std::string value_type_name(const openvdb::GridBase& grid) {
  const std::string type = grid.valueType();
  return type == "float" && grid.saveFloatAsHalf() ? "half" : type;
}

bool is_scalar_grid(const openvdb::GridBase& grid) {
  return grid.isType<openvdb::FloatGrid>() || grid.isType<openvdb::DoubleGrid>() ||
         grid.isType<openvdb::Int32Grid>() || grid.isType<openvdb::Int64Grid>();
}

openvdb::FloatGrid::Ptr to_float_grid(const openvdb::GridBase::Ptr& grid) {
  if (auto same = openvdb::gridPtrCast<openvdb::FloatGrid>(grid)) return same;
  openvdb::FloatGrid::Ptr out;
  // Tree's converting constructor casts every value and tile of a tree with
  // the same 5-4-3 configuration; the background is cast with them.
  const bool converted =
      grid->apply<openvdb::TypeList<openvdb::DoubleGrid, openvdb::Int32Grid, openvdb::Int64Grid>>(
          [&out](const auto& typed) {
            out = openvdb::FloatGrid::create(std::make_shared<openvdb::FloatTree>(typed.tree()));
          });
  if (!converted) throw InvalidArgument("grid '" + grid->getName() + "' is not a scalar grid");
  out->insertMeta(*grid);
  out->setTransform(grid->transform().copy());
  out->setSaveFloatAsHalf(false);
  return out;
}

}  // namespace isoform::vdbio
