// Neighbours and parts inside one brick (Hamann 1991, Algorithms 3.1, 3.2).
#include "brick_topology.h"

#include <algorithm>
#include <climits>

namespace isoform {
namespace {

int next(int i) { return i == 2 ? 0 : i + 1; }

}  // namespace

int32_t BrickTopology::run(const int32_t* tris, size_t nt, const uint8_t* shared, const int32_t* final_vertex,
                           int64_t first_triangle, int32_t* neighbours, int32_t* parts, TopologyCounts& total,
                           std::vector<SeamEdge>& seams) {
  TopologyCounts counts;  // local, so that it stays in registers
  // The triangle edges of each undirected local edge, grouped in a hash
  // table: compute_neighbours finds the same groups by its vertex scan.
  size_t size = 16;
  while (size < 3 * nt) size *= 2;
  const int shift = 64 - __builtin_ctzll(size);
  // The table stays empty between calls: only the slots used are cleared.
  if (table_.size() < size) table_.assign(size, Slot{kEmpty, -1, -1});
  used_.clear();
  for (size_t at = 0; at < 3 * nt; ++at) {
    const size_t t = at / 3;
    const int32_t a = tris[at], b = tris[3 * t + size_t(next(int(at - 3 * t)))];
    neighbours[at] = -1;
    if (shared[a] && shared[b]) {
      const uint64_t fa = uint64_t(final_vertex[a]), fb = uint64_t(final_vertex[b]);
      seams.push_back({fa < fb ? (fa << 32) | fb : (fb << 32) | fa, uint64_t(3 * first_triangle) + at});
      continue;
    }
    const uint64_t key = a < b ? (uint64_t(a) << 32) | uint64_t(b) : (uint64_t(b) << 32) | uint64_t(a);
    size_t h = size_t((key * 0x9E3779B97F4A7C15ull) >> shift);
    while (table_[h].key != kEmpty && table_[h].key != key) h = (h + 1) & (size - 1);
    Slot& slot = table_[h];
    if (slot.key == kEmpty) {
      slot = Slot{key, int32_t(at), -1};
      used_.push_back(uint32_t(h));
    } else {
      slot.second = slot.second == -1 ? int32_t(at) : kMore;
    }
  }
  root_.resize(nt);
  for (size_t t = 0; t < nt; ++t) root_[t] = int32_t(t);
  auto find = [&](int32_t x) {
    while (root_[size_t(x)] != x) x = root_[size_t(x)] = root_[size_t(root_[size_t(x)])];
    return x;
  };
  const auto runs_up = [&](int32_t e) {
    const int32_t t = e / 3;
    return tris[e] < tris[3 * t + next(e - 3 * t)];
  };
  for (uint32_t h : used_) {
    Slot& slot = table_[h];
    ++counts.edges;
    if (slot.second == -1) {
      ++counts.boundary;
    } else if (slot.second >= 0) {
      const int32_t t = slot.first / 3, u = slot.second / 3;
      neighbours[size_t(slot.first)] = int32_t(first_triangle) + u;
      neighbours[size_t(slot.second)] = int32_t(first_triangle) + t;
      counts.inconsistent += runs_up(slot.first) == runs_up(slot.second);
      const int32_t ra = find(t), rb = find(u);
      if (ra != rb) root_[size_t(std::max(ra, rb))] = std::min(ra, rb);
    } else {
      ++counts.nonmanifold;
    }
    slot = Slot{kEmpty, -1, -1};
  }
  total.add(counts);
  // Roots are the smallest triangle of their part: number them in order.
  int32_t label = 0;
  for (size_t t = 0; t < nt; ++t) {
    const int32_t r = find(int32_t(t));
    parts[t] = size_t(r) == t ? label++ : parts[size_t(r)];
  }
  return label;
}

}  // namespace isoform
