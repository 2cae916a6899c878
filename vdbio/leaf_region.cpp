// LeafBricks::fill_region: a dense box read straight from the tree, so that
// the interiors of tiles and the background come out with their own values
// (bricks only cover leaves and tile boundaries).
#include "leaf_bricks.h"

namespace isoform::vdbio {

void LeafBricks::fill_region(const Index3& lo, const Index3& dims, float /*outside*/,
                             std::vector<float>& out) const {
  out.resize(size_t(dims[0]) * size_t(dims[1]) * size_t(dims[2]));
  // An unregistered accessor: the tree is not modified while it is read; it
  // caches the last leaf, so a row costs one tree descent per leaf it meets.
  openvdb::tree::ValueAccessor<const openvdb::FloatTree, false> access(grid_->tree());
  size_t at = 0;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
        out[at++] = access.getValue(openvdb::Coord(lo[0] + i, lo[1] + j, lo[2] + k));
}

}  // namespace isoform::vdbio
