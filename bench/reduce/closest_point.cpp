// Point-to-triangle distance by the Voronoi regions of the triangle's
// corners and edges, and a median-split bounding-box tree traversed nearest
// box first with pruning by the best distance found so far.
#include "closest_point.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isoform_reduce_bench {
namespace {

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm2(const Vec3& a) { return dot(a, a); }

// Squared distance from p to the point a + t (b - a).
double to_point_on(const Vec3& p, const Vec3& a, const Vec3& b, double t) {
  const Vec3 q{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
  return norm2(sub(p, q));
}

double point_segment_distance2(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = sub(b, a);
  const double len2 = norm2(ab);
  if (len2 == 0) return norm2(sub(p, a));
  return to_point_on(p, a, b, std::clamp(dot(sub(p, a), ab) / len2, 0.0, 1.0));
}

double box_distance2(const double lo[3], const double hi[3], const Vec3& p) {
  double d2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double d = std::max({lo[k] - p[k], 0.0, p[k] - hi[k]});
    d2 += d * d;
  }
  return d2;
}

Vec3 corner(const double* c, int i) { return {c[3 * i], c[3 * i + 1], c[3 * i + 2]}; }

constexpr uint32_t kLeafSize = 4;

}  // namespace

double point_triangle_distance2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = sub(b, a), ac = sub(c, a);
  const Vec3 n{ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]};
  if (norm2(n) <= 1e-30 * norm2(ab) * norm2(ac) || norm2(n) == 0)
    return std::min({point_segment_distance2(p, a, b), point_segment_distance2(p, b, c),
                     point_segment_distance2(p, c, a)});
  const Vec3 ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return norm2(ap);  // corner a
  const Vec3 bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return norm2(bp);  // corner b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return to_point_on(p, a, b, d1 / (d1 - d3));  // edge ab
  const Vec3 cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return norm2(cp);  // corner c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return to_point_on(p, a, c, d2 / (d2 - d6));  // edge ac
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return to_point_on(p, b, c, (d4 - d3) / ((d4 - d3) + (d5 - d6)));  // edge bc
  // Inside: the distance to the plane.
  const double h = dot(ap, n);
  return h * h / norm2(n);
}

TriangleTree::TriangleTree(const MeshView& mesh) {
  const size_t m = mesh.triangle_count;
  if (m == 0) return;
  std::vector<double> centroids(3 * m);
  for (size_t t = 0; t < m; ++t)
    for (int k = 0; k < 3; ++k) {
      double s = 0;
      for (int i = 0; i < 3; ++i) s += mesh.points[3 * size_t(mesh.triangles[3 * t + i]) + k];
      centroids[3 * t + k] = s / 3;
    }
  std::vector<uint32_t> order(m);
  for (size_t t = 0; t < m; ++t) order[t] = uint32_t(t);
  nodes_.reserve(2 * m / kLeafSize + 2);
  // The corners in input order first; build() sorts `order`, then they are laid out in leaf order.
  corners_.resize(9 * m);
  for (size_t t = 0; t < m; ++t)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) corners_[9 * t + 3 * i + k] = mesh.points[3 * size_t(mesh.triangles[3 * t + i]) + k];
  build(order, centroids, 0, uint32_t(m));
  std::vector<double> sorted(9 * m);
  for (size_t s = 0; s < m; ++s) std::copy_n(&corners_[9 * size_t(order[s])], 9, &sorted[9 * s]);
  corners_.swap(sorted);
  input_index_ = order;
}

uint32_t TriangleTree::build(std::vector<uint32_t>& order, const std::vector<double>& centroids, uint32_t begin,
                             uint32_t end) {
  const uint32_t at = uint32_t(nodes_.size());
  nodes_.push_back(Node{});
  Node node;
  double clo[3], chi[3];
  for (int k = 0; k < 3; ++k) {
    node.lo[k] = clo[k] = std::numeric_limits<double>::infinity();
    node.hi[k] = chi[k] = -std::numeric_limits<double>::infinity();
  }
  for (uint32_t s = begin; s < end; ++s) {
    const double* c = &corners_[9 * size_t(order[s])];
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) {
        node.lo[k] = std::min(node.lo[k], c[3 * i + k]);
        node.hi[k] = std::max(node.hi[k], c[3 * i + k]);
      }
    for (int k = 0; k < 3; ++k) {
      clo[k] = std::min(clo[k], centroids[3 * size_t(order[s]) + k]);
      chi[k] = std::max(chi[k], centroids[3 * size_t(order[s]) + k]);
    }
  }
  if (end - begin <= kLeafSize) {
    node.first = begin;
    node.count = end - begin;
    nodes_[at] = node;
    return at;
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
  const uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                   [&](uint32_t a, uint32_t b) { return centroids[3 * size_t(a) + axis] < centroids[3 * size_t(b) + axis]; });
  build(order, centroids, begin, mid);
  node.first = build(order, centroids, mid, end);
  node.count = 0;
  nodes_[at] = node;
  return at;
}

double TriangleTree::distance2(const Vec3& p, int32_t* nearest) const {
  double best = std::numeric_limits<double>::infinity();
  uint32_t best_at = 0;
  if (nearest) *nearest = -1;
  if (nodes_.empty()) return best;
  uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (box_distance2(node.lo, node.hi, p) >= best) continue;
    if (node.count > 0) {
      for (uint32_t s = node.first; s < node.first + node.count; ++s) {
        const double* c = &corners_[9 * size_t(s)];
        const double d2 = point_triangle_distance2(p, corner(c, 0), corner(c, 1), corner(c, 2));
        if (d2 < best) best = d2, best_at = s;
      }
      continue;
    }
    const uint32_t left = uint32_t(&node - nodes_.data()) + 1, right = node.first;
    const double dl = box_distance2(nodes_[left].lo, nodes_[left].hi, p);
    const double dr = box_distance2(nodes_[right].lo, nodes_[right].hi, p);
    // The nearer child is popped first.
    if (dl <= dr) {
      if (dr < best) stack[top++] = right;
      if (dl < best) stack[top++] = left;
    } else {
      if (dl < best) stack[top++] = left;
      if (dr < best) stack[top++] = right;
    }
  }
  if (nearest && best < std::numeric_limits<double>::infinity()) *nearest = int32_t(input_index_[best_at]);
  return best;
}

}  // namespace isoform_reduce_bench
