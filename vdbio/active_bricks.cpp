// Bricks of a float tree with the active set as their defined flags.
#include "active_bricks.h"

#include <algorithm>

namespace isoform::vdbio {

namespace {

using openvdb::Coord;
using Tree = openvdb::FloatTree;
constexpr int kBlock = int(Tree::LeafNodeType::DIM);

std::vector<Coord> active_blocks(const Tree& tree) {
  std::vector<Coord> out;
  for (auto leaf = tree.cbeginLeaf(); leaf; ++leaf)
    if (!leaf->isEmpty()) out.push_back(leaf->origin());
  auto tile = tree.cbeginValueOn();
  tile.setMaxDepth(Tree::ValueOnCIter::LEAF_DEPTH - 1);  // tiles only, no voxels
  for (; tile; ++tile) {
    openvdb::CoordBBox box;
    tile.getBoundingBox(box);
    for (int z = box.min().z(); z <= box.max().z(); z += kBlock)
      for (int y = box.min().y(); y <= box.max().y(); y += kBlock)
        for (int x = box.min().x(); x <= box.max().x(); x += kBlock) out.emplace_back(x, y, z);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

ActiveBricks::ActiveBricks(openvdb::FloatGrid::ConstPtr grid)
    : grid_(std::move(grid)), origins_(active_blocks(grid_->tree())) {}

void ActiveBricks::fill(size_t index, Brick& out) const {
  const Coord origin = origins_[index];
  out.resize({origin.x(), origin.y(), origin.z()}, {kBlock, kBlock, kBlock}, true);
  openvdb::tree::ValueAccessor<const Tree, false> access(grid_->tree());
  const Index3 d = out.dims();
  size_t at = 0;
  for (int k = -1; k < d[2] - 1; ++k)
    for (int j = -1; j < d[1] - 1; ++j)
      for (int i = -1; i < d[0] - 1; ++i, ++at) {
        const Coord p = origin.offsetBy(i, j, k);
        float v = 0.0f;
        out.defined[at] = access.probeValue(p, v) ? 1 : 0;
        out.samples[at] = v;
      }
}

}  // namespace isoform::vdbio
