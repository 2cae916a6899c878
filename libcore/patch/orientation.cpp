// Folds of the side-vertex surface: patches whose orientation disagrees with
// their neighbour's along a shared edge (orientation.h).
#include "orientation.h"

namespace isoform::patch {

bool inverted_triangle(const SideVertexSurface& s, size_t t) {
  const V3d& a = s.vertex(size_t(s.triangle_vertex(t, 0)));
  const V3d& b = s.vertex(size_t(s.triangle_vertex(t, 1)));
  const V3d& c = s.vertex(size_t(s.triangle_vertex(t, 2)));
  V3d n(0.0, 0.0, 0.0);
  for (int i = 0; i < 3; ++i) n = n + s.vertex_normal(size_t(s.triangle_vertex(t, i)));
  return dot(cross(b - a, c - a), n) < 0.0;
}

namespace {

// Bits per edge: some patch agrees with n_S (1), some disagrees (2).
constexpr uint8_t kAgrees = 1, kDisagrees = 2;

// The orientation of triangle t's patch along its edge slot i against n_S,
// by majority over the samples; 0 when no sample could be evaluated.
uint8_t edge_orientation(const SideVertexSurface& s, size_t t, int i, int samples) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const TriangleEdge te = s.triangle_edge(t, i);
  int agree = 0, disagree = 0;
  for (int q = 0; q < samples; ++q) {
    const double f = (q + 0.5) / samples;  // weight on local vertex k
    double bary[3] = {0.0, 0.0, 0.0};
    bary[j] = 1.0 - f;
    bary[k] = f;
    SurfaceSample x;
    if (!s.evaluate_order(t, bary[1], bary[2], x, false)) continue;
    const V3d n_s = edge_eval(s.edge_curve(size_t(te.edge)), te.reversed ? 1.0 - f : f).normal;
    const double d = dot(V3d::from(x.normal), n_s);
    (d >= 0.0 ? agree : disagree) += 1;
  }
  if (agree + disagree == 0) return 0;
  return agree >= disagree ? kAgrees : kDisagrees;
}

}  // namespace

FoldReport find_folds(const SideVertexSurface& s, int samples) {
  FoldReport r;
  std::vector<uint8_t> seen(s.edge_count(), 0);
  for (size_t t = 0; t < s.triangle_count(); ++t) {
    if (inverted_triangle(s, t)) ++r.inverted_triangles;
    for (int i = 0; i < 3; ++i) seen[size_t(s.triangle_edge(t, i).edge)] |= edge_orientation(s, t, i, samples);
  }
  for (size_t e = 0; e < seen.size(); ++e)
    if (seen[e] == (kAgrees | kDisagrees)) r.edges.push_back(int32_t(e));
  r.folded_edges = (long long)r.edges.size();
  return r;
}

}  // namespace isoform::patch
