// Seam edges across bricks, and part labels over the whole mesh.
#include "seams.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <memory>

#include "fresh_memory.h"
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

}  // namespace

void match_seams(SeamEdge* seams, size_t n, size_t vertex_count, std::vector<int32_t>& neighbours,
                 const std::vector<int32_t>& parts, TopologyCounts& counts,
                 std::vector<std::pair<int32_t, int32_t>>& links) {
  {
    // Both vertices of a key are below vertex_count: sort by the two packed
    // side by side. Stable, so equal keys keep their increasing edges, which
    // is the order of (key, edge).
    const int vb = radix_bits_for(vertex_count > 0 ? uint64_t(vertex_count - 1) : 0);
    const std::unique_ptr<SeamEdge[]> buffer = fresh_array<SeamEdge>(n);
    radix_sort(seams, buffer.get(), n, 2 * vb,
               [vb](const SeamEdge& e) { return ((e.key >> 32) << vb) | (e.key & 0xFFFFFFFFu); });
  }
  tbb::enumerable_thread_specific<GroupScratch> scratch;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& r) {
    GroupScratch& s = scratch.local();
    // Each range handles the groups that start in it.
    size_t i = r.begin();
    while (i > 0 && i < r.end() && seams[i].key == seams[i - 1].key) ++i;
    while (i < r.end()) {
      size_t j = i + 1;
      while (j < n && seams[j].key == seams[i].key) ++j;
      match_group(&seams[i], j - i, neighbours, parts, s);
      i = j;
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
