// Six tetrahedra per cell and their contour triangles (Section 3.2).
#include "tetra.h"

#include <algorithm>
#include <vector>

namespace isoform {
namespace {

using P3 = std::array<double, 3>;

P3 corner_point(int c) { return {double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1)}; }
P3 midpoint(int a, int b) {
  const P3 p = corner_point(a), q = corner_point(b);
  return {(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2};
}
P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
P3 cross(const P3& a, const P3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Reverses the polygon unless its normal points toward `toward`. The
// orientation found at edge midpoints holds for every crossing position: the
// polygon is planar and convex for every position, and cannot flip without
// degenerating.
TetPolygon oriented(TetPolygon poly, const P3& toward) {
  const P3 a = midpoint(poly.edges[0][0], poly.edges[0][1]), b = midpoint(poly.edges[1][0], poly.edges[1][1]),
           c = midpoint(poly.edges[2][0], poly.edges[2][1]);
  if (dot(cross(sub(b, a), sub(c, a)), sub(toward, a)) < 0) std::reverse(poly.edges.begin(), poly.edges.begin() + poly.size);
  return poly;
}

TetPolygon build_case(const std::array<int, 4>& tet, int above) {
  int up[4], down[4], nu = 0, nd = 0;
  for (int m = 0; m < 4; ++m) (above >> m & 1 ? up[nu++] : down[nd++]) = tet[m];
  auto e = [](int a, int b) { return std::array<uint8_t, 2>{uint8_t(a), uint8_t(b)}; };
  TetPolygon poly;
  if (nu == 0 || nu == 4) return poly;
  // The normal points toward the centroid of the above corners, which lies
  // on the above side of the contour plane.
  P3 c{0, 0, 0};
  for (int i = 0; i < nu; ++i)
    for (int a = 0; a < 3; ++a) c[a] += corner_point(up[i])[a] / nu;
  if (nu == 1) {
    poly.size = 3;
    poly.edges = {e(up[0], down[0]), e(up[0], down[1]), e(up[0], down[2]), {}};
  } else if (nu == 3) {
    poly.size = 3;
    poly.edges = {e(down[0], up[0]), e(down[0], up[1]), e(down[0], up[2]), {}};
  } else {
    poly.size = 4;
    poly.edges = {e(up[0], down[0]), e(up[0], down[1]), e(up[1], down[1]), e(up[1], down[0])};
  }
  return oriented(poly, c);
}

}  // namespace

const std::array<std::array<int, 4>, 6>& tetrahedra() {
  // Corner ids (u | v << 1 | w << 2) of T1..T6 as printed in Section 3.2.
  static const std::array<std::array<int, 4>, 6> tets = {{{0, 1, 2, 4},
                                                          {1, 2, 4, 6},
                                                          {1, 5, 4, 6},
                                                          {1, 3, 2, 6},
                                                          {1, 3, 5, 6},
                                                          {3, 5, 6, 7}}};
  return tets;
}

const TetPolygon& tet_polygon(int t, int above) {
  static const std::vector<TetPolygon> table = [] {
    std::vector<TetPolygon> all(6 * 16);
    for (int tt = 0; tt < 6; ++tt)
      for (int a = 0; a < 16; ++a) all[tt * 16 + a] = build_case(tetrahedra()[tt], a);
    return all;
  }();
  return table[t * 16 + above];
}

}  // namespace isoform
