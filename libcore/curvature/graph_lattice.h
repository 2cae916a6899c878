// Finds bricks by position when a BrickSource's bricks tile index space on a
// regular lattice (vdbio's leaf bricks, dense arrays cut into bricks): one
// origin every `pitch` samples per axis, each brick at most pitch cells.
#pragma once

#include <utility>
#include <vector>

#include "../volume.h"

namespace isoform {

class BrickLattice {
 public:
  static constexpr size_t npos = size_t(-1);

  // From each brick's origin and cells, in brick order. Bricks that are not
  // on one lattice leave it empty: find() then finds nothing.
  explicit BrickLattice(const std::vector<std::pair<Index3, Index3>>& bricks);

  bool valid() const { return valid_; }
  // The brick whose own samples [origin, origin + cells) hold p, or npos.
  size_t find(const Index3& p) const;
  // The brick whose lattice cell is `step` cells from brick b's, or npos.
  size_t neighbour(size_t b, const Index3& step) const;

 private:
  Index3 key_of(const Index3& p) const;
  size_t find_key(const Index3& key) const;

  bool valid_ = false;
  Index3 base_{0, 0, 0}, pitch_{1, 1, 1};
  std::vector<std::pair<Index3, Index3>> bricks_;
  std::vector<std::pair<Index3, size_t>> sorted_;  // lattice key -> brick
};

}  // namespace isoform
