// Merging per-brick vertex and triangle tables into one shared-vertex mesh.
#include "merge.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <cmath>

namespace isoform {
namespace {

struct Offsets {
  std::vector<size_t> vertex, triangle;  // per brick, exclusive prefix sums
  std::vector<size_t> shared;
};

Offsets prefix_sums(const std::vector<BrickMesh>& bricks) {
  Offsets o;
  const size_t n = bricks.size();
  o.vertex.resize(n + 1, 0);
  o.triangle.resize(n + 1, 0);
  o.shared.resize(n + 1, 0);
  for (size_t b = 0; b < n; ++b) {
    o.vertex[b + 1] = o.vertex[b] + bricks[b].points.size() / 3;
    o.triangle[b + 1] = o.triangle[b] + bricks[b].triangles.size() / 3;
    o.shared[b + 1] = o.shared[b] + bricks[b].shared.size();
  }
  return o;
}

// For every provisional vertex, the provisional vertex that represents it:
// itself, or the first copy of the same edge crossing in another brick.
std::vector<int64_t> representatives(const std::vector<BrickMesh>& bricks, const Offsets& o) {
  std::vector<int64_t> rep(o.vertex.back());
  tbb::parallel_for(size_t(0), rep.size(), [&](size_t v) { rep[v] = int64_t(v); });
  std::vector<std::pair<uint64_t, int64_t>> keys(o.shared.back());
  tbb::parallel_for(size_t(0), bricks.size(), [&](size_t b) {
    size_t at = o.shared[b];
    for (const auto& s : bricks[b].shared) keys[at++] = {s.first, int64_t(o.vertex[b]) + s.second};
  });
  tbb::parallel_sort(keys.begin(), keys.end());
  for (size_t i = 1; i < keys.size(); ++i)
    if (keys[i].first == keys[i - 1].first) rep[size_t(keys[i].second)] = rep[size_t(keys[i - 1].second)];
  return rep;
}

}  // namespace

void merge_bricks(std::vector<BrickMesh>& bricks, Mesh& mesh) {
  const Offsets o = prefix_sums(bricks);
  const std::vector<int64_t> rep = representatives(bricks, o);
  // Final index of each kept vertex: a prefix sum over the keep flags.
  std::vector<int32_t> final_index(rep.size());
  int32_t next = 0;
  for (size_t v = 0; v < rep.size(); ++v)
    if (rep[v] == int64_t(v)) final_index[v] = next++;
  mesh.points.resize(3 * size_t(next));
  mesh.normals.resize(3 * size_t(next));
  mesh.triangles.resize(3 * o.triangle.back());
  tbb::parallel_for(size_t(0), bricks.size(), [&](size_t b) {
    BrickMesh& bm = bricks[b];
    const size_t base = o.vertex[b];
    for (size_t v = 0; v < bm.points.size() / 3; ++v) {
      if (rep[base + v] != int64_t(base + v)) continue;
      const size_t to = 3 * size_t(final_index[base + v]);
      const float* g = &bm.gradients[3 * v];
      const double len = std::sqrt(double(g[0]) * g[0] + double(g[1]) * g[1] + double(g[2]) * g[2]);
      for (int a = 0; a < 3; ++a) {
        mesh.points[to + a] = bm.points[3 * v + a];
        mesh.normals[to + a] = len > 0 ? float(g[a] / len) : 0.0f;
      }
    }
    size_t t = 3 * o.triangle[b];
    for (int32_t local : bm.triangles) mesh.triangles[t++] = final_index[size_t(rep[base + size_t(local)])];
    BrickMesh().points.swap(bm.points);
    BrickMesh().gradients.swap(bm.gradients);
    BrickMesh().triangles.swap(bm.triangles);
  });
  for (const BrickMesh& bm : bricks) {
    mesh.contour.ambiguous_faces += bm.stats.ambiguous_faces;
    mesh.contour.degenerate_saddles += bm.stats.degenerate_saddles;
    mesh.contour.extra_points += bm.stats.extra_points;
    mesh.contour.centroid_points += bm.stats.centroid_points;
    mesh.contour.near_sample_points += bm.stats.near_sample_points;
  }
}

}  // namespace isoform
