// Neighbours and parts inside one brick (Hamann 1991, Algorithms 3.1, 3.2).
#include "brick_topology.h"

#include <algorithm>
#include <climits>

namespace isoform {
namespace {

int next(int i) { return i == 2 ? 0 : i + 1; }

}  // namespace

void BrickTopology::half_edges(const int32_t* tris, size_t nt, size_t nv) {
  // Counts, then inclusive sums (start_[v] = end of v's run), then a fill
  // from the back that moves each start_[v] down to the beginning of its run.
  start_.assign(nv + 1, 0);
  for (size_t c = 0; c < 3 * nt; ++c) ++start_[size_t(tris[c])];
  for (size_t v = 1; v < nv; ++v) start_[v] += start_[v - 1];
  start_[nv] = int32_t(3 * nt);
  out_.resize(3 * nt);
  for (size_t c = 3 * nt; c-- > 0;) {
    const size_t t = c / 3;
    const int i = int(c - 3 * t);
    out_[size_t(--start_[size_t(tris[c])])] = {tris[3 * t + size_t(next(i))], int32_t(c)};
  }
}

int32_t BrickTopology::run(const int32_t* tris, size_t nt, size_t nv, const uint8_t* shared,
                           const int32_t* final_vertex, int64_t first_triangle, int32_t* neighbours,
                           int32_t* parts, TopologyCounts& counts, std::vector<SeamEdge>& seams) {
  half_edges(tris, nt, nv);
  root_.resize(nt);
  done_.assign(3 * nt, 0);
  for (size_t t = 0; t < nt; ++t) root_[t] = int32_t(t);
  auto find = [&](int32_t x) {
    while (root_[size_t(x)] != x) x = root_[size_t(x)] = root_[size_t(root_[size_t(x)])];
    return x;
  };
  for (size_t t = 0; t < nt; ++t) {
    const int32_t* tri = &tris[3 * t];
    for (int i = 0; i < 3; ++i) {
      const int32_t a = tri[i], b = tri[next(i)];
      const size_t at = 3 * t + size_t(i);
      if (done_[at]) continue;  // matched from its neighbour's side
      if (shared[a] && shared[b]) {
        const uint64_t fa = uint64_t(final_vertex[a]), fb = uint64_t(final_vertex[b]);
        seams.push_back({fa < fb ? (fa << 32) | fb : (fb << 32) | fa, uint64_t(3 * first_triangle) + at});
        continue;
      }
      // As compute_neighbours: the other triangles that hold a and b. Each
      // (having three distinct vertices) runs one half-edge between them:
      // from b to a when consistently oriented with t, else from a to b.
      // Branch-free: which entries match is not predictable.
      int count = 0;
      int32_t other = -1, lowest_other = INT32_MAX;
      bool same_direction = false;
      for (int32_t s = start_[size_t(a)]; s < start_[size_t(a) + 1]; ++s) {
        const HalfEdge& h = out_[size_t(s)];
        const bool hit = (h.to == b) & (h.edge != int32_t(at));
        count += hit;
        other = hit ? h.edge : other;
        lowest_other = hit ? std::min(lowest_other, h.edge) : lowest_other;
        same_direction |= hit;
      }
      for (int32_t s = start_[size_t(b)]; s < start_[size_t(b) + 1]; ++s) {
        const HalfEdge& h = out_[size_t(s)];
        const bool hit = h.to == a;
        count += hit;
        other = hit ? h.edge : other;
        lowest_other = hit ? std::min(lowest_other, h.edge) : lowest_other;
      }
      const bool lowest = lowest_other == INT32_MAX || size_t(lowest_other / 3) > t;
      counts.edges += lowest;
      neighbours[at] = -1;
      if (count == 0) {
        ++counts.boundary;
      } else if (count == 1) {
        // Both sides at once: the neighbour's edge needs no search.
        const int32_t u = other / 3;
        neighbours[at] = int32_t(first_triangle + u);
        neighbours[size_t(other)] = int32_t(first_triangle) + int32_t(t);
        done_[size_t(other)] = 1;
        counts.inconsistent += same_direction;
        const int32_t ra = find(int32_t(t)), rb = find(u);
        if (ra != rb) root_[size_t(std::max(ra, rb))] = std::min(ra, rb);
      } else if (lowest) {
        ++counts.nonmanifold;
      }
    }
  }
  // Roots are the smallest triangle of their part: number them in order.
  int32_t label = 0;
  for (size_t t = 0; t < nt; ++t) {
    const int32_t r = find(int32_t(t));
    parts[t] = size_t(r) == t ? label++ : parts[size_t(r)];
  }
  return label;
}

}  // namespace isoform
