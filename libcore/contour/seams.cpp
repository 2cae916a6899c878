// Seam edges across bricks, and part labels over the whole mesh.
#include "seams.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <memory>

#include "../fresh_memory.h"
#include "radix_sort.h"

namespace isoform {
namespace {

struct GroupScratch {
  TopologyCounts counts;
  std::vector<std::pair<int32_t, int32_t>> links;
};

void match_group(const SeamEdge* g, size_t n, std::vector<int32_t>& neighbours, const std::vector<int32_t>& parts,
                 GroupScratch& s) {
  ++s.counts.edges;
  for (size_t m = 0; m < n; ++m) neighbours[size_t(g[m].triangle_edge())] = -1;
  if (n == 1) {
    ++s.counts.boundary;
  } else if (n == 2) {
    const int32_t t = int32_t(g[0].triangle_edge() / 3), u = int32_t(g[1].triangle_edge() / 3);
    neighbours[size_t(g[0].triangle_edge())] = u;
    neighbours[size_t(g[1].triangle_edge())] = t;
    if (g[0].runs_up() == g[1].runs_up()) ++s.counts.inconsistent;
    // The local parts to join; neighbouring groups often join the same two.
    const std::pair<int32_t, int32_t> link(parts[size_t(t)], parts[size_t(u)]);
    if (link.first != link.second && (s.links.empty() || s.links.back() != link)) s.links.push_back(link);
  } else {
    ++s.counts.nonmanifold;
  }
}

uint64_t smaller_vertex(const SeamEdge& e) { return e.key >> 32; }

// A stable insertion sort by key: the run of one smaller vertex holds a
// handful of edges (those of its few sides, once or twice each).
void sort_by_key(SeamEdge* run, size_t n) {
  for (size_t i = 1; i < n; ++i) {
    const SeamEdge e = run[i];
    size_t j = i;
    for (; j > 0 && run[j - 1].key > e.key; --j) run[j] = run[j - 1];
    run[j] = e;
  }
}

// Where the pieces of about kPiece edges begin, each moved up to the start
// of a run of one smaller vertex; n closes the last one.
std::vector<size_t> run_starts(const SeamEdge* seams, size_t n) {
  constexpr size_t kPiece = 4096;
  std::vector<size_t> starts;
  for (size_t at = 0; at < n; at += kPiece) {
    size_t i = at;
    while (i > 0 && i < n && smaller_vertex(seams[i]) == smaller_vertex(seams[i - 1])) ++i;
    starts.push_back(i);
  }
  starts.push_back(n);
  return starts;
}

}  // namespace

void match_seams(SeamEdge* seams, size_t n, size_t vertex_count, std::vector<int32_t>& neighbours,
                 const std::vector<int32_t>& parts, TopologyCounts& counts,
                 std::vector<std::pair<int32_t, int32_t>>& links) {
  {
    // By the smaller vertex only, half the passes of sorting by both; the
    // few edges that share a smaller vertex are put in key order below.
    // Stable, so equal keys keep their increasing edges, which is the order
    // of (key, edge).
    const int vb = radix_bits_for(vertex_count > 0 ? uint64_t(vertex_count - 1) : 0);
    const ScratchArray<SeamEdge> buffer(n);
    radix_sort(seams, buffer.get(), n, vb, [](const SeamEdge& e) { return e.key >> 32; });
  }
  // Pieces of the sorted edges that begin where a run of one smaller
  // vertex begins, found before any run is reordered; each piece puts its
  // runs in key order and matches their groups.
  const std::vector<size_t> starts = run_starts(seams, n);
  tbb::enumerable_thread_specific<GroupScratch> scratch;
  tbb::parallel_for(size_t(0), starts.size() - 1, [&](size_t p) {
    GroupScratch& s = scratch.local();
    for (size_t i = starts[p], end; i < starts[p + 1]; i = end) {
      end = i + 1;
      while (end < n && smaller_vertex(seams[end]) == smaller_vertex(seams[i])) ++end;
      sort_by_key(seams + i, end - i);
      for (size_t g = i, h; g < end; g = h) {
        h = g + 1;
        while (h < end && seams[h].key == seams[g].key) ++h;
        match_group(&seams[g], h - g, neighbours, parts, s);
      }
    }
  });
  for (GroupScratch& s : scratch) {
    counts.add(s.counts);
    links.insert(links.end(), s.links.begin(), s.links.end());
  }
}

int32_t number_parts(std::vector<int32_t>& parts, std::vector<int64_t> size,
                     const std::vector<std::pair<int32_t, int32_t>>& links) {
  const size_t local_parts = size.size();
  std::vector<int32_t> root(local_parts);
  for (size_t g = 0; g < local_parts; ++g) root[g] = int32_t(g);
  auto find = [&](int32_t x) {
    while (root[size_t(x)] != x) x = root[size_t(x)] = root[size_t(root[size_t(x)])];
    return x;
  };
  // The smallest local part is the one with the smallest first triangle,
  // so roots by smallest index are the roots compute_parts finds.
  for (const auto& l : links) {
    const int32_t a = find(l.first), b = find(l.second);
    if (a != b) root[size_t(std::max(a, b))] = std::min(a, b);
  }
  std::vector<int32_t> roots;
  for (size_t g = 0; g < local_parts; ++g) {
    const int32_t r = find(int32_t(g));
    if (size_t(r) == g)
      roots.push_back(r);
    else
      size[size_t(r)] += size[g];
  }
  std::stable_sort(roots.begin(), roots.end(),
                   [&](int32_t a, int32_t b) { return size[size_t(a)] > size[size_t(b)]; });
  std::vector<int32_t> label(local_parts, -1);
  for (size_t r = 0; r < roots.size(); ++r) label[size_t(roots[r])] = int32_t(r);
  for (size_t g = 0; g < local_parts; ++g) label[g] = label[size_t(root[g])];
  tbb::parallel_for(tbb::blocked_range<size_t>(0, parts.size(), 1 << 16), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t t = r.begin(); t != r.end(); ++t) parts[t] = label[size_t(parts[t])];
  });
  return int32_t(roots.size());
}

}  // namespace isoform
