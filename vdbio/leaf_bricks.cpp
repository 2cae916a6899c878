// Bricks over an OpenVDB float tree: candidate blocks and their samples.
#include "leaf_bricks.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace isoform::vdbio {

namespace {

using openvdb::Coord;
using Tree = openvdb::FloatTree;
using Leaf = Tree::LeafNodeType;

constexpr int kBlock = int(Leaf::DIM);  // 8: candidates are found per block of the leaves' grid
// Cells per brick and axis: 2 blocks. NOTE: against bricks of one block,
// a brick's halo and its shared crossings and gradients on brick faces are
// a smaller part of its work, and per-brick costs are spread over 8 times
// the cells. Bricks of 4 blocks measured slower on a narrow-band level set,
// where a brick of 64 blocks around a thin band holds many blocks with no
// crossing that are filled and scanned all the same.
constexpr int kCells = 16;
constexpr int kSpan = kCells / kBlock;  // blocks per brick and axis
static_assert(kCells % kBlock == 0 && (kCells & (kCells - 1)) == 0, "bricks are whole, aligned blocks");

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

// Origins of the blocks that can hold a crossing cell (leaf_bricks.h).
std::vector<Coord> candidate_blocks(const Tree& tree) {
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

Coord brick_of(const Coord& c) {
  return Coord(c.x() & ~(kCells - 1), c.y() & ~(kCells - 1), c.z() & ~(kCells - 1));
}

// The bricks that hold a candidate block, sorted.
std::vector<Coord> brick_origins(const std::vector<Coord>& blocks) {
  std::vector<Coord> out;
  out.reserve(blocks.size());
  for (const Coord& c : blocks) out.push_back(brick_of(c));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// A brick's 19 samples per axis (origin - 1 .. origin + 17) come from the
// block below (its last sample), its own 2 blocks (all 8 of each) and the
// block above (its first two).
constexpr int kSamples = kCells + 3;
constexpr int kBlocks = kSpan + 2;

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

// Per brick: the range over the blocks that hold its corner samples
// (origin .. origin + kCells per axis). Every leaf is a candidate block, so
// a block that is not one lies in one tile or the background.
void corner_ranges(const Tree& tree, const std::vector<Coord>& blocks, const std::vector<Coord>& bricks,
                   std::vector<float>& lo, std::vector<float>& hi) {
  std::vector<float> own_lo, own_hi;
  block_ranges(tree, blocks, own_lo, own_hi);
  lo.resize(bricks.size());
  hi.resize(bricks.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, bricks.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
    openvdb::tree::ValueAccessor<const Tree, false> access(tree);
    for (size_t b = r.begin(); b != r.end(); ++b) {
      float a = std::numeric_limits<float>::infinity(), z = -a;
      for (int dz = 0; dz <= kSpan; ++dz)
        for (int dy = 0; dy <= kSpan; ++dy)
          for (int dx = 0; dx <= kSpan; ++dx) {
            const Coord at = bricks[b].offsetBy(dx * kBlock, dy * kBlock, dz * kBlock);
            const auto it = std::lower_bound(blocks.begin(), blocks.end(), at);
            if (it != blocks.end() && *it == at) {
              const size_t o = size_t(it - blocks.begin());
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

LeafBricks::LeafBricks(openvdb::FloatGrid::ConstPtr grid) : grid_(std::move(grid)) {
  const std::vector<Coord> blocks = candidate_blocks(grid_->tree());
  origins_ = brick_origins(blocks);
  corner_ranges(grid_->tree(), blocks, origins_, corner_min_, corner_max_);
}

void LeafBricks::fill(size_t index, Brick& out) const {
  const Coord origin = origins_[index];
  out.resize({origin.x(), origin.y(), origin.z()}, {kCells, kCells, kCells}, false);
  // An unregistered accessor: the tree is not modified while bricks are read.
  openvdb::tree::ValueAccessor<const Tree, false> access(grid_->tree());
  Block blocks[kBlocks][kBlocks][kBlocks];
  for (int bz = 0; bz < kBlocks; ++bz)
    for (int by = 0; by < kBlocks; ++by)
      for (int bx = 0; bx < kBlocks; ++bx) {
        const Coord at = origin.offsetBy((bx - 1) * kBlock, (by - 1) * kBlock, (bz - 1) * kBlock);
        Block& block = blocks[bz][by][bx];
        if (const Leaf* leaf = access.probeConstLeaf(at))
          block.values = leaf->buffer().data();
        else
          block.constant = access.getValue(at);
      }
  // Leaf buffers hold z fastest (offset x*64 + y*8 + z); bricks hold x
  // fastest. Sample s of an axis is index origin + s - 1.
  constexpr int kX = kBlock * kBlock;
  const auto block_of = [](int s) { return (s - 1 + kBlock) / kBlock; };
  const auto local = [](int s) { return (s - 1 + kBlock) % kBlock; };
  float* sample = out.samples.data();
  for (int k = 0; k < kSamples; ++k)
    for (int j = 0; j < kSamples; ++j, sample += kSamples) {
      const Block* row = blocks[block_of(k)][block_of(j)];
      const int yz = local(j) * kBlock + local(k);
      sample[0] = row[0].values ? row[0].values[(kBlock - 1) * kX + yz] : row[0].constant;
      for (int m = 1; m <= kSpan; ++m) {
        float* to = sample + 1 + (m - 1) * kBlock;
        if (const float* v = row[m].values) {
          for (int x = 0; x < kBlock; ++x) to[x] = v[x * kX + yz];
        } else {
          for (int x = 0; x < kBlock; ++x) to[x] = row[m].constant;
        }
      }
      if (const float* v = row[kSpan + 1].values) {
        sample[kCells + 1] = v[yz];
        sample[kCells + 2] = v[kX + yz];
      } else {
        sample[kCells + 1] = sample[kCells + 2] = row[kSpan + 1].constant;
      }
    }
}

}  // namespace isoform::vdbio
