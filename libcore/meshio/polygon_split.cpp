// Polygon faces to triangles: the fan for convex polygons, ear clipping in
// the polygon's projection for the others, the fan again when the polygon
// has no plane or no ear.
#include "polygon_split.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace isoform::meshio {
namespace {

using Point3 = std::array<double, 3>;
using Point2 = std::array<double, 2>;

// Twice the signed area of triangle abc: positive when a, b, c turn left.
double orient(const Point2& a, const Point2& b, const Point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// Triangles (0, k, k+1) for k = 1 .. n-2.
void append_fan(const std::vector<int32_t>& corners, std::vector<int32_t>& out) {
  for (size_t k = 1; k + 1 < corners.size(); ++k) {
    out.insert(out.end(), {corners[0], corners[k], corners[k + 1]});
  }
}

bool all_finite(const std::vector<Point3>& points) {
  return std::all_of(points.begin(), points.end(), [](const Point3& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  });
}

Point3 relative(const Point3& p, const Point3& origin) {
  return {p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]};
}

// Newell's normal, twice the polygon's vector area, with positions taken
// relative to the first corner so that a polygon far from the origin keeps
// its precision. Component k is twice the signed area of the projection
// onto the plane of coordinates k+1 and k+2 (cyclically).
Point3 newell_normal(const std::vector<Point3>& points) {
  Point3 normal{0, 0, 0};
  for (size_t i = 0; i < points.size(); ++i) {
    Point3 p = relative(points[i], points[0]);
    Point3 q = relative(points[(i + 1) % points.size()], points[0]);
    for (size_t k = 0; k < 3; ++k) {
      size_t u = (k + 1) % 3;
      size_t v = (k + 2) % 3;
      normal[k] += (p[u] - q[u]) * (p[v] + q[v]);
    }
  }
  return normal;
}

// Twice the signed area of a polygon in the plane, relative to its first
// corner.
double signed_area(const std::vector<Point2>& polygon) {
  double twice = 0;
  for (size_t i = 1; i + 1 < polygon.size(); ++i) {
    twice += orient(polygon[0], polygon[i], polygon[i + 1]);
  }
  return twice;
}

// The positions in the coordinate plane that drops the largest component of
// the Newell normal, with the two kept coordinates in the order that makes
// the polygon turn left there. Coordinates are copied, not computed, so the
// orientation tests later see the file's own numbers. False when the polygon
// has no plane or its projection has no positive area.
bool project(const std::vector<Point3>& points, std::vector<Point2>& projected) {
  if (!all_finite(points)) return false;
  Point3 normal = newell_normal(points);
  size_t drop = 0;
  for (size_t k = 1; k < 3; ++k) {
    if (std::fabs(normal[k]) > std::fabs(normal[drop])) drop = k;
  }
  if (!(std::fabs(normal[drop]) > 0) || !std::isfinite(normal[drop])) return false;
  size_t u = (drop + 1) % 3;
  size_t v = (drop + 2) % 3;
  if (normal[drop] < 0) std::swap(u, v);
  projected.clear();
  for (const Point3& p : points) projected.push_back({p[u], p[v]});
  double area = signed_area(projected);
  return std::isfinite(area) && area > 0;
}

// Every corner a left turn.
bool strictly_convex(const std::vector<Point2>& polygon) {
  size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    if (!(orient(polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]) > 0)) return false;
  }
  return true;
}

// The smallest angle of a triangle that turns left, as minus its cosine:
// larger is better shaped.
double shape(const Point2& a, const Point2& b, const Point2& c) {
  const Point2* corner[3] = {&a, &b, &c};
  double largest_cosine = -1;
  for (int k = 0; k < 3; ++k) {
    const Point2& o = *corner[k];
    const Point2& p = *corner[(k + 1) % 3];
    const Point2& q = *corner[(k + 2) % 3];
    double px = p[0] - o[0], py = p[1] - o[1], qx = q[0] - o[0], qy = q[1] - o[1];
    double cosine = (px * qx + py * qy) / (std::hypot(px, py) * std::hypot(qx, qy));
    largest_cosine = std::max(largest_cosine, cosine);
  }
  return -largest_cosine;
}

bool in_closed_triangle(const Point2& a, const Point2& b, const Point2& c, const Point2& p) {
  return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
}

// Ear clipping of a projected polygon that turns left. The remaining corners
// form a ring in corner order; each keeps its ear's shape, or kNotAnEar, and
// only the two neighbours of a cut corner are looked at again. Cutting a
// corner can also free an ear elsewhere whose triangle held it, so when no
// ear is left on record every corner is looked at again before giving up.
class EarClipper {
 public:
  explicit EarClipper(const std::vector<Point2>& polygon);
  // Corner-number triples of the triangles; false when no ear is left.
  bool run(std::vector<size_t>& triangles);

 private:
  static constexpr double kNotAnEar = -std::numeric_limits<double>::infinity();

  void rate_all();
  void rate(size_t corner);
  bool blocks_nothing(size_t a, size_t b, size_t c) const;
  size_t best() const;
  void cut(size_t corner, std::vector<size_t>& triangles);

  const std::vector<Point2>& polygon_;
  std::vector<size_t> next_, prev_;
  std::vector<double> ear_;
  size_t first_ = 0;  // the remaining corner of lowest number
  size_t remaining_;
};

EarClipper::EarClipper(const std::vector<Point2>& polygon)
    : polygon_(polygon),
      next_(polygon.size()),
      prev_(polygon.size()),
      ear_(polygon.size(), kNotAnEar),
      remaining_(polygon.size()) {
  size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    next_[i] = (i + 1) % n;
    prev_[i] = (i + n - 1) % n;
  }
}

bool EarClipper::run(std::vector<size_t>& triangles) {
  rate_all();
  while (remaining_ > 3) {
    size_t corner = best();
    if (ear_[corner] == kNotAnEar) {
      rate_all();
      corner = best();
      if (ear_[corner] == kNotAnEar) return false;
    }
    cut(corner, triangles);
  }
  size_t a = first_, b = next_[a], c = next_[b];
  if (!(orient(polygon_[a], polygon_[b], polygon_[c]) > 0)) return false;
  triangles.insert(triangles.end(), {a, b, c});
  return true;
}

void EarClipper::rate_all() {
  size_t corner = first_;
  do {
    rate(corner);
    corner = next_[corner];
  } while (corner != first_);
}

// A corner is an ear when it turns left and its triangle with its
// neighbours holds no other remaining corner.
void EarClipper::rate(size_t corner) {
  size_t a = prev_[corner], c = next_[corner];
  const Point2 &pa = polygon_[a], &pb = polygon_[corner], &pc = polygon_[c];
  bool ear = orient(pa, pb, pc) > 0 && blocks_nothing(a, corner, c);
  ear_[corner] = ear ? shape(pa, pb, pc) : kNotAnEar;
}

bool EarClipper::blocks_nothing(size_t a, size_t b, size_t c) const {
  for (size_t p = next_[c]; p != a; p = next_[p]) {
    if (in_closed_triangle(polygon_[a], polygon_[b], polygon_[c], polygon_[p])) return false;
  }
  return true;
}

// The ear of the best shape; the first in corner order among equals.
size_t EarClipper::best() const {
  size_t chosen = first_;
  for (size_t corner = next_[first_]; corner != first_; corner = next_[corner]) {
    if (ear_[corner] > ear_[chosen]) chosen = corner;
  }
  return chosen;
}

void EarClipper::cut(size_t corner, std::vector<size_t>& triangles) {
  size_t a = prev_[corner], c = next_[corner];
  triangles.insert(triangles.end(), {a, corner, c});
  next_[a] = c;
  prev_[c] = a;
  if (corner == first_) first_ = c;
  --remaining_;
  rate(a);
  rate(c);
}

// Ear clipping's triangles in vertex indices; false (out untouched) when it
// found no ear.
bool append_ears(const std::vector<int32_t>& corners, const std::vector<Point2>& projected,
                 std::vector<int32_t>& out) {
  std::vector<size_t> triangles;
  triangles.reserve(3 * (corners.size() - 2));
  if (!EarClipper(projected).run(triangles)) return false;
  for (size_t corner : triangles) out.push_back(corners[corner]);
  return true;
}

}  // namespace

void split_polygon(const std::vector<int32_t>& corners,
                   const std::function<std::array<double, 3>(int32_t)>& point,
                   std::vector<int32_t>& out) {
  if (corners.size() < 3) return;
  if (corners.size() == 3 || corners.size() > kMostCornersToClip) {
    append_fan(corners, out);
    return;
  }
  std::vector<Point3> points;
  points.reserve(corners.size());
  for (int32_t vertex : corners) points.push_back(point(vertex));
  std::vector<Point2> projected;
  projected.reserve(corners.size());
  if (project(points, projected) && !strictly_convex(projected) &&
      append_ears(corners, projected, out)) {
    return;
  }
  append_fan(corners, out);
}

}  // namespace isoform::meshio
