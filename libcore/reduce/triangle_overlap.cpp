// The triangle pair test of the self-overlap check (see triangle_overlap.h).
// Triangles in general position cross exactly when an edge of one crosses
// the other's inside: its ends strictly on both sides of the plane, and the
// line passing the three edges the same way (the signs of the tetrahedra
// p q t_i t_i+1 agree).
#include "triangle_overlap.h"

#include <algorithm>
#include <cmath>

namespace isoform::reduce {
namespace {

using Point2 = std::array<double, 2>;

// Rounding bounds relative to the pair's extent D (the largest side of the
// box around both triangles), which bounds every difference vector: the
// determinants have 6 (3D) and 2 (2D) products, each off by a few units of
// 2^-53 from the differences, the products and the sums.
constexpr double kBound3 = 2e-14, kBound2 = 1e-14;

Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

Point3 cross(const Point3& u, const Point3& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

double dot(const Point3& u, const Point3& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

double largest(const Point3& u) { return std::max({std::fabs(u[0]), std::fabs(u[1]), std::fabs(u[2])}); }

Point3 normal(const Point3 t[3]) { return cross(sub(t[1], t[0]), sub(t[2], t[0])); }

// Which side of a plane a point lies on: +1 on the normal's side, -1 on the
// other, 0 when rounding could decide it.
struct Side {
  double value;
  int sign;
};

// The bounds of one pair.
struct Bounds {
  double b3 = 0, b2 = 0;
  Bounds(const Point3 a[3], const Point3 b[3]) {
    double d = 0;
    for (int k = 0; k < 3; ++k) {
      const double lo = std::min({a[0][k], a[1][k], a[2][k], b[0][k], b[1][k], b[2][k]});
      const double hi = std::max({a[0][k], a[1][k], a[2][k], b[0][k], b[1][k], b[2][k]});
      d = std::max(d, hi - lo);
    }
    b3 = kBound3 * d * d * d;
    b2 = kBound2 * d * d;
  }
  Side side(double det) const { return {det, det > b3 ? 1 : det < -b3 ? -1 : 0}; }
  int sign2(double det) const { return det > b2 ? 1 : det < -b2 ? -1 : 0; }
};

// The side of the plane through t0 with normal n (n = normal(t)).
Side orient3d(const Bounds& k, const Point3& t0, const Point3& n, const Point3& d) { return k.side(dot(n, sub(d, t0))); }

Side orient3d(const Bounds& k, const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return orient3d(k, a, cross(sub(b, a), sub(c, a)), d);
}

struct Triangle {
  const Point3* p;  // three corners
  Point3 n;         // (p1 - p0) x (p2 - p0)
  Side side(const Bounds& k, const Point3& d) const { return orient3d(k, p[0], n, d); }
};

int orient2d(const Bounds& k, const Point2& a, const Point2& b, const Point2& c) {
  return k.sign2((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

Point3 mix(const Point3& p, const Point3& q, double w) {
  return {p[0] + w * (q[0] - p[0]), p[1] + w * (q[1] - p[1]), p[2] + w * (q[2] - p[2])};
}

Point3 centroid(const Point3 t[3]) {
  return {(t[0][0] + t[1][0] + t[2][0]) / 3, (t[0][1] + t[1][1] + t[2][1]) / 3, (t[0][2] + t[1][2] + t[2][2]) / 3};
}

// ---------------------------------------------------------------- in a plane

// Drops the largest axis of n.
struct Projection {
  int u = 0, v = 1;
  explicit Projection(const Point3& n) {
    const double ax = std::fabs(n[0]), ay = std::fabs(n[1]), az = std::fabs(n[2]);
    const int drop = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    u = (drop + 1) % 3;
    v = (drop + 2) % 3;
  }
  Point2 operator()(const Point3& p) const { return {p[size_t(u)], p[size_t(v)]}; }
};

// The projection of the better defined of two planes.
Projection common_plane(const Triangle& a, const Triangle& b) {
  return Projection(largest(a.n) >= largest(b.n) ? a.n : b.n);
}

// Some edge of t (turning o) has no corner of u certainly inside it.
bool separates(const Bounds& k, const Point2 t[3], int o, const Point2 u[3]) {
  for (int e = 0; e < 3; ++e) {
    const Point2 &a = t[e], &b = t[(e + 1) % 3];
    if (orient2d(k, a, b, u[0]) * o <= 0 && orient2d(k, a, b, u[1]) * o <= 0 && orient2d(k, a, b, u[2]) * o <= 0)
      return true;
  }
  return false;
}

// Insides overlap: no edge line of either separates them (two convex
// polygons apart have a separating line along one of their edges).
bool insides_overlap_2d(const Bounds& k, const Point2 a[3], const Point2 b[3]) {
  const int oa = orient2d(k, a[0], a[1], a[2]), ob = orient2d(k, b[0], b[1], b[2]);
  if (oa == 0 || ob == 0) return false;  // a segment in this projection
  return !separates(k, a, oa, b) && !separates(k, b, ob, a);
}

// The line through s and x (with y on its side turning o) has p and q on
// its other side or on it.
bool splits(const Bounds& k, const Point2& s, const Point2& x, const Point2& y, const Point2& p, const Point2& q) {
  const int o = orient2d(k, s, x, y);
  return o == 0 || (orient2d(k, s, x, p) * o <= 0 && orient2d(k, s, x, q) * o <= 0);
}

// Wedges at s (less than half-planes) have overlapping insides unless the
// line of one of their rays separates them.
bool wedges_overlap(const Bounds& k, const Point2& s, const Point2& a1, const Point2& a2, const Point2& b1,
                    const Point2& b2) {
  return !splits(k, s, a1, a2, b1, b2) && !splits(k, s, a2, a1, b1, b2) && !splits(k, s, b1, b2, a1, a2) &&
         !splits(k, s, b2, b1, a1, a2);
}

// ---------------------------------------------------------------- in space

// The segment pq crosses t's inside, certainly; where.
bool segment_crosses(const Bounds& k, const Point3& p, const Point3& q, const Triangle& t, Point3* at) {
  const Side sp = t.side(k, p), sq = t.side(k, q);
  if (sp.sign * sq.sign >= 0) return false;
  const Point3* c = t.p;
  const int s0 = orient3d(k, p, q, c[0], c[1]).sign;
  if (s0 == 0 || orient3d(k, p, q, c[1], c[2]).sign != s0 || orient3d(k, p, q, c[2], c[0]).sign != s0) return false;
  *at = mix(p, q, sp.value / (sp.value - sq.value));
  return true;
}

bool one_side(int x, int y) { return x * y > 0; }

bool one_side(int x, int y, int z) { return (x > 0 && y > 0 && z > 0) || (x < 0 && y < 0 && z < 0); }

PairOverlap no_shared_vertex(const Bounds& k, const Triangle& a, const Triangle& b) {
  const int db[3] = {a.side(k, b.p[0]).sign, a.side(k, b.p[1]).sign, a.side(k, b.p[2]).sign};
  if (one_side(db[0], db[1], db[2])) return {};
  const int da[3] = {b.side(k, a.p[0]).sign, b.side(k, a.p[1]).sign, b.side(k, a.p[2]).sign};
  if (one_side(da[0], da[1], da[2])) return {};
  PairOverlap r;
  if (da[0] == 0 && da[1] == 0 && da[2] == 0 && db[0] == 0 && db[1] == 0 && db[2] == 0) {
    const Projection pr = common_plane(a, b);
    const Point2 a2[3] = {pr(a.p[0]), pr(a.p[1]), pr(a.p[2])}, b2[3] = {pr(b.p[0]), pr(b.p[1]), pr(b.p[2])};
    r.overlap = insides_overlap_2d(k, a2, b2);
    r.near = mix(centroid(a.p), centroid(b.p), 0.5);
    return r;
  }
  for (int i = 0; i < 3; ++i)
    if (segment_crosses(k, a.p[i], a.p[(i + 1) % 3], b, &r.near) ||
        segment_crosses(k, b.p[i], b.p[(i + 1) % 3], a, &r.near)) {
      r.overlap = true;
      return r;
    }
  return {};
}

// a and b share corner s; a's other corners a1 a2, b's b1 b2.
PairOverlap one_shared_vertex(const Bounds& k, const Triangle& a, const Triangle& b, const Point3& s,
                              const Point3& a1, const Point3& a2, const Point3& b1, const Point3& b2) {
  const int d1 = a.side(k, b1).sign, d2 = a.side(k, b2).sign;
  if (one_side(d1, d2)) return {};
  const int e1 = b.side(k, a1).sign, e2 = b.side(k, a2).sign;
  PairOverlap r;
  if (d1 == 0 && d2 == 0 && e1 == 0 && e2 == 0) {  // one plane: do the wedges at s overlap?
    const Projection pr = common_plane(a, b);
    r.overlap = wedges_overlap(k, pr(s), pr(a1), pr(a2), pr(b1), pr(b2));
    r.near = mix(centroid(a.p), centroid(b.p), 0.5);
    return r;
  }
  if (one_side(e1, e2)) return {};
  r.overlap = segment_crosses(k, a1, a2, b, &r.near) || segment_crosses(k, b1, b2, a, &r.near);
  return r;
}

// a and b share the edge uv; c and d are their third corners.
PairOverlap shared_edge(const Bounds& k, const Triangle& a, const Triangle& b, const Point3& u, const Point3& v,
                        const Point3& c, const Point3& d) {
  if (a.side(k, d).sign != 0 || b.side(k, c).sign != 0) return {};
  const Projection pr = common_plane(a, b);
  const Point2 U = pr(u), V = pr(v);
  PairOverlap r;
  r.overlap = orient2d(k, U, V, pr(c)) * orient2d(k, U, V, pr(d)) > 0;  // folded onto each other
  r.near = mix(mix(u, v, 0.5), mix(c, d, 0.5), 0.5);
  return r;
}

bool degenerate(const Point3& n) { return !(n[0] != 0 || n[1] != 0 || n[2] != 0); }

}  // namespace

Point3 triangle_normal(const Point3 t[3]) { return normal(t); }

bool certainly_apart(const Point3 pa[3], const Point3& na, const int32_t ia[3], const Point3 pb[3], const Point3& nb,
                     const int32_t ib[3], double extent) {
  const double bound = 2 * (kBound3 * extent * extent * extent);
  // The corners of q not shared with the other triangle, strictly on one
  // side of the plane through p0 with normal n (counted without branches:
  // which way a pair goes is as good as random).
  auto one_side_of = [&](const Point3& p0, const Point3& n, const Point3 q[3], const int32_t iq[3], const int32_t ip[3]) {
    int above = 0, below = 0, off = 0;
    for (int j = 0; j < 3; ++j) {
      const int own = (iq[j] != ip[0]) & (iq[j] != ip[1]) & (iq[j] != ip[2]);
      const double det = dot(n, sub(q[j], p0));
      off += own;
      above += own & int(det > bound);
      below += own & int(det < -bound);
    }
    return (off > 0) & ((above == off) | (below == off));
  };
  return one_side_of(pa[0], na, pb, ib, ia) || one_side_of(pb[0], nb, pa, ia, ib);
}

PairOverlap triangles_overlap(const Point3 pa[3], const int32_t ia[3], const Point3 pb[3], const int32_t ib[3]) {
  return triangles_overlap(pa, normal(pa), ia, pb, normal(pb), ib);
}

PairOverlap triangles_overlap(const Point3 pa[3], const Point3& na, const int32_t ia[3], const Point3 pb[3],
                              const Point3& nb, const int32_t ib[3]) {
  const Triangle a{pa, na}, b{pb, nb};
  if (degenerate(a.n) || degenerate(b.n)) return {};
  const Bounds k(pa, pb);
  int in_b[3] = {-1, -1, -1};  // for each corner of a, the same vertex's corner in b
  int shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (ia[i] == ib[j]) {
        in_b[i] = j;
        ++shared;
      }
  if (shared == 0) return no_shared_vertex(k, a, b);
  if (shared >= 3) return {true, centroid(pa)};
  if (shared == 1) {
    const int i = in_b[0] >= 0 ? 0 : in_b[1] >= 0 ? 1 : 2, j = in_b[i];
    return one_shared_vertex(k, a, b, pa[i], pa[(i + 1) % 3], pa[(i + 2) % 3], pb[(j + 1) % 3], pb[(j + 2) % 3]);
  }
  const int i = in_b[0] < 0 ? 0 : in_b[1] < 0 ? 1 : 2;      // a's corner off the edge
  const int j = 3 - in_b[(i + 1) % 3] - in_b[(i + 2) % 3];  // b's
  return shared_edge(k, a, b, pa[(i + 1) % 3], pa[(i + 2) % 3], pa[i], pb[j]);
}

}  // namespace isoform::reduce
