// Shared-vertex keys (edge_key, brick_contour.h) packed with a provisional
// vertex index into one 64-bit word, where the grid's extent allows: each
// index coordinate relative to the smallest one met, in as many bits as the
// largest needs. Packing keeps the order of the (key, vertex) pairs, so a
// sort of the words gives the pairs' sorted order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "brick_contour.h"

namespace isoform {

struct PackedLayout {
  bool fits = false;                 // false: the pairs need more than 64 bits
  uint64_t low[3] = {0, 0, 0};       // smallest coordinate per axis (as in the key)
  int shift[3] = {0, 0, 0};          // where each coordinate goes
  int vertex_bits = 0;               // the provisional vertex's bits (lowest)
  int bits = 0;                      // every packed word is below 2^bits
  uint64_t pack(uint64_t key, uint64_t vertex) const {
    const uint64_t x = key >> 43, y = (key >> 23) & 0xFFFFF, z = (key >> 3) & 0xFFFFF;
    return ((x - low[0]) << shift[0]) | ((y - low[1]) << shift[1]) | ((z - low[2]) << shift[2]) |
           ((key & 7) << vertex_bits) | vertex;
  }
};

// The layout for the shared keys of these bricks, with vertex indices below
// vertex_count. Runs in parallel with TBB.
PackedLayout packed_layout(const std::vector<BrickMesh>& bricks, size_t vertex_count);

}  // namespace isoform
