// Bricks over an OpenVDB float tree: candidate blocks and their samples.
#include "leaf_bricks.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace isoform::vdbio {

namespace {

using openvdb::Coord;
using Tree = openvdb::FloatTree;
using Leaf = Tree::LeafNodeType;

constexpr int kBlock = int(Leaf::DIM);  // 8: bricks and leaves share the grid
static_assert(kBlock == 8, "brick tables below assume 8^3 leaves");

// The block itself and the 7 below it: a cell whose lower corner lies in
// one of those has an upper corner in this block.
void add_with_lower_neighbours(const Coord& origin, std::vector<Coord>& out) {
  for (int dz = 0; dz >= -kBlock; dz -= kBlock)
    for (int dy = 0; dy >= -kBlock; dy -= kBlock)
      for (int dx = 0; dx >= -kBlock; dx -= kBlock) out.push_back(origin.offsetBy(dx, dy, dz));
}

// Cells with corners inside and outside the tile have their lower corner
// in [min - 1, max] on each axis with at least one axis at an end, so their
// blocks are those of the range [min - 8, max - 7] on its boundary.
void add_tile_shell(const openvdb::CoordBBox& tile, std::vector<Coord>& out) {
  const Coord lo = tile.min().offsetBy(-kBlock);
  const Coord hi = tile.max().offsetBy(1 - kBlock);
  for (int z = lo.z(); z <= hi.z(); z += kBlock) {
    for (int y = lo.y(); y <= hi.y(); y += kBlock) {
      const bool on_side = z == lo.z() || z == hi.z() || y == lo.y() || y == hi.y();
      // Inside the range only the first and last block of a row are on it.
      const int step = on_side ? kBlock : hi.x() - lo.x();
      for (int x = lo.x(); x <= hi.x(); x += step) out.emplace_back(x, y, z);
    }
  }
}

std::vector<Coord> candidate_origins(const Tree& tree) {
  std::vector<Coord> out;
  out.reserve(size_t(tree.leafCount()) * 8);
  for (auto leaf = tree.cbeginLeaf(); leaf; ++leaf) add_with_lower_neighbours(leaf->origin(), out);
  auto tile = tree.cbeginValueOn();
  tile.setMaxDepth(Tree::ValueOnCIter::LEAF_DEPTH - 1);  // tiles only, no voxels
  for (; tile; ++tile) {
    openvdb::CoordBBox box;
    tile.getBoundingBox(box);
    add_tile_shell(box, out);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// A brick's 11 samples per axis (origin - 1 .. origin + 9) come from the
// blocks below (its last sample), at (all 8) and above (its first two).
constexpr int kSamples = kBlock + 3;
constexpr int kBlockOf[kSamples] = {0, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2};
constexpr int kLocal[kSamples] = {7, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1};

// One of the 27 blocks around a brick: a leaf's values, or a constant.
struct Block {
  const float* values = nullptr;
  float constant = 0.0f;
};

// Per origin: the value range of its block alone (a leaf's buffer, or the
// one tile or background value of a block without a leaf).
void block_ranges(const Tree& tree, const std::vector<Coord>& origins, std::vector<float>& lo,
                  std::vector<float>& hi) {
  lo.resize(origins.size());
  hi.resize(origins.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, origins.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
    openvdb::tree::ValueAccessor<const Tree, false> access(tree);
    for (size_t b = r.begin(); b != r.end(); ++b) {
      if (const Leaf* leaf = access.probeConstLeaf(origins[b])) {
        const float* v = leaf->buffer().data();
        float a = v[0], z = v[0];
        for (size_t m = 1; m < Leaf::SIZE; ++m) {
          a = std::min(a, v[m]);
          z = std::max(z, v[m]);
        }
        lo[b] = a;
        hi[b] = z;
      } else {
        lo[b] = hi[b] = access.getValue(origins[b]);
      }
    }
  });
}

// Per brick: the range over its block and the 7 above it, which hold all
// its corner samples. Every leaf is an origin (candidate_origins), so a
// block that is not one lies in one tile or the background.
void corner_ranges(const Tree& tree, const std::vector<Coord>& origins, std::vector<float>& lo,
                   std::vector<float>& hi) {
  std::vector<float> own_lo, own_hi;
  block_ranges(tree, origins, own_lo, own_hi);
  lo.resize(origins.size());
  hi.resize(origins.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, origins.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
    openvdb::tree::ValueAccessor<const Tree, false> access(tree);
    for (size_t b = r.begin(); b != r.end(); ++b) {
      float a = own_lo[b], z = own_hi[b];
      for (int c = 1; c < 8; ++c) {
        const Coord at = origins[b].offsetBy((c & 1) * kBlock, ((c >> 1) & 1) * kBlock, (c >> 2) * kBlock);
        const auto it = std::lower_bound(origins.begin() + std::ptrdiff_t(b), origins.end(), at);
        if (it != origins.end() && *it == at) {
          const size_t o = size_t(it - origins.begin());
          a = std::min(a, own_lo[o]);
          z = std::max(z, own_hi[o]);
        } else {
          const float v = access.getValue(at);
          a = std::min(a, v);
          z = std::max(z, v);
        }
      }
      lo[b] = a;
      hi[b] = z;
    }
  });
}

}  // namespace

LeafBricks::LeafBricks(openvdb::FloatGrid::ConstPtr grid)
    : grid_(std::move(grid)), origins_(candidate_origins(grid_->tree())) {
  corner_ranges(grid_->tree(), origins_, corner_min_, corner_max_);
}

void LeafBricks::fill(size_t index, Brick& out) const {
  const Coord origin = origins_[index];
  out.resize({origin.x(), origin.y(), origin.z()}, {kBlock, kBlock, kBlock}, false);
  // An unregistered accessor: the tree is not modified while bricks are read.
  openvdb::tree::ValueAccessor<const Tree, false> access(grid_->tree());
  Block blocks[3][3][3];
  for (int bz = 0; bz < 3; ++bz)
    for (int by = 0; by < 3; ++by)
      for (int bx = 0; bx < 3; ++bx) {
        const Coord at = origin.offsetBy((bx - 1) * kBlock, (by - 1) * kBlock, (bz - 1) * kBlock);
        Block& block = blocks[bz][by][bx];
        if (const Leaf* leaf = access.probeConstLeaf(at))
          block.values = leaf->buffer().data();
        else
          block.constant = access.getValue(at);
      }
  // Leaf buffers hold z fastest (offset x*64 + y*8 + z); bricks hold x fastest.
  // Per row of 11 samples: the last x of the block below, all 8 of the
  // block, the first two of the block above.
  constexpr int kX = kBlock * kBlock;
  float* sample = out.samples.data();
  for (int k = 0; k < kSamples; ++k)
    for (int j = 0; j < kSamples; ++j, sample += kSamples) {
      const Block* row = blocks[kBlockOf[k]][kBlockOf[j]];
      const int yz = kLocal[j] * kBlock + kLocal[k];
      sample[0] = row[0].values ? row[0].values[(kBlock - 1) * kX + yz] : row[0].constant;
      if (const float* v = row[1].values) {
        for (int x = 0; x < kBlock; ++x) sample[1 + x] = v[x * kX + yz];
      } else {
        for (int x = 0; x < kBlock; ++x) sample[1 + x] = row[1].constant;
      }
      if (const float* v = row[2].values) {
        sample[kBlock + 1] = v[yz];
        sample[kBlock + 2] = v[kX + yz];
      } else {
        sample[kBlock + 1] = sample[kBlock + 2] = row[2].constant;
      }
    }
}

}  // namespace isoform::vdbio
