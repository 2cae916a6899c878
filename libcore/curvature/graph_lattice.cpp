// Bricks on a regular lattice, found by binary search on their lattice keys.
#include "graph_lattice.h"

#include <algorithm>

namespace isoform {
namespace {

int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

}  // namespace

BrickLattice::BrickLattice(const std::vector<std::pair<Index3, Index3>>& bricks) : bricks_(bricks) {
  if (bricks.empty()) return;
  base_ = bricks[0].first;
  for (const auto& b : bricks)
    for (int a = 0; a < 3; ++a) pitch_[a] = std::max(pitch_[a], b.second[a]);
  for (const auto& b : bricks)
    for (int a = 0; a < 3; ++a)
      if ((b.first[a] - base_[a]) % pitch_[a] != 0) return;
  sorted_.reserve(bricks.size());
  for (size_t i = 0; i < bricks.size(); ++i) sorted_.emplace_back(key_of(bricks[i].first), i);
  std::sort(sorted_.begin(), sorted_.end());
  for (size_t i = 1; i < sorted_.size(); ++i)
    if (sorted_[i].first == sorted_[i - 1].first) {  // two bricks in one lattice cell
      sorted_.clear();
      return;
    }
  valid_ = true;
}

Index3 BrickLattice::key_of(const Index3& p) const {
  return {floor_div(p[0] - base_[0], pitch_[0]), floor_div(p[1] - base_[1], pitch_[1]),
          floor_div(p[2] - base_[2], pitch_[2])};
}

size_t BrickLattice::find_key(const Index3& key) const {
  const auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::make_pair(key, size_t(0)));
  return it != sorted_.end() && it->first == key ? it->second : npos;
}

size_t BrickLattice::find(const Index3& p) const {
  if (!valid_) return npos;
  const size_t b = find_key(key_of(p));
  if (b == npos) return npos;
  const auto& [origin, cells] = bricks_[b];
  for (int a = 0; a < 3; ++a)
    if (p[a] < origin[a] || p[a] >= origin[a] + cells[a]) return npos;
  return b;
}

size_t BrickLattice::neighbour(size_t b, const Index3& step) const {
  if (!valid_) return npos;
  const Index3 k = key_of(bricks_[b].first);
  return find_key({k[0] + step[0], k[1] + step[1], k[2] + step[2]});
}

}  // namespace isoform
