// The combinatorics of one cell: corners, edges and faces, fixed once.
//
// Corner c of a cell is (c & 1, c >> 1 & 1, c >> 2 & 1) in (u, v, w).
// Edge e runs along axis e / 4 from the corner whose other two coordinates
// are the bits of e % 4 (lower axis first): e0..e3 along u, e4..e7 along v,
// e8..e11 along w. Face f lies at u_a = s with a = f / 2, s = f % 2.
#pragma once

#include <array>

namespace isoform::cell {

constexpr int corner(int u, int v, int w) { return u | (v << 1) | (w << 2); }

// The two corners of edge e, the lower one first.
inline std::array<int, 2> edge_corners(int e) {
  const int a = e / 4, b0 = e & 1, b1 = (e >> 1) & 1;
  int lo[3], hi[3];
  const int o1 = (a + 1) % 3, o2 = (a + 2) % 3;
  // Bits of e % 4 hold the other two coordinates in increasing axis order.
  const int first = o1 < o2 ? o1 : o2, second = o1 < o2 ? o2 : o1;
  lo[a] = 0;
  hi[a] = 1;
  lo[first] = hi[first] = b0;
  lo[second] = hi[second] = b1;
  return {corner(lo[0], lo[1], lo[2]), corner(hi[0], hi[1], hi[2])};
}

// The edge joining corners p and q, which differ in exactly one coordinate.
inline int edge_between(int p, int q) {
  const int diff = p ^ q;
  const int a = diff == 1 ? 0 : diff == 2 ? 1 : 2;
  const int c = p & ~diff;
  int bits[2], n = 0;
  for (int b = 0; b < 3; ++b)
    if (b != a) bits[n++] = (c >> b) & 1;
  return 4 * a + bits[0] + 2 * bits[1];
}

// The four corners of face f in counter-clockwise order seen from outside
// the cell. With (b, c) = (a + 1, a + 2) mod 3, (b, c, a) is right-handed,
// so (0,0), (1,0), (1,1), (0,1) in (b, c) is counter-clockwise seen from +a
// (face s = 1); seen from -a (s = 0) the order reverses.
inline std::array<int, 4> face_corners(int f) {
  const int a = f / 2, s = f % 2, b = (a + 1) % 3, c = (a + 2) % 3;
  static const int ccw[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::array<int, 4> out{};
  for (int m = 0; m < 4; ++m) {
    const int q = s == 1 ? m : (4 - m) % 4;
    int x[3];
    x[a] = s;
    x[b] = ccw[q][0];
    x[c] = ccw[q][1];
    out[m] = corner(x[0], x[1], x[2]);
  }
  return out;
}

}  // namespace isoform::cell
