// Hamann (1991), Section 3.2: contour polygons of a cell under the trilinear
// interpolant, and the extra interior point of Theorem 3.6.
#include "cell_polygons.h"

#include <cmath>

#include "cell_table.h"

namespace isoform {
namespace {

struct Segment {
  int from_edge = -1, to_edge = -1, face = -1;
};

// The segments of face f, each from an exit crossing (walking the face's
// boundary counter-clockwise from outside, leaving the above region) to an
// entry crossing, so that the above region lies on the segment's left.
int face_segments(const double g[8], int f, Segment out[2], bool* ambiguous, bool* degenerate) {
  const std::array<int, 4> q = cell::face_corners(f);
  int exits[2], entries[2], n_exit = 0, n_entry = 0, exit_slot[2] = {0, 0};
  int edge_of[4];
  for (int m = 0; m < 4; ++m) {
    const int p = q[m], r = q[(m + 1) % 4];
    edge_of[m] = cell::edge_between(p, r);
    const bool above_p = g[p] > 0, above_r = g[r] > 0;
    if (above_p && !above_r) {
      exit_slot[n_exit] = m;
      exits[n_exit++] = edge_of[m];
    } else if (!above_p && above_r) {
      entries[n_entry++] = edge_of[m];
    }
  }
  *ambiguous = false;
  *degenerate = false;
  if (n_exit == 0) return 0;
  if (n_exit == 1) {
    out[0] = {exits[0], entries[0], f};
    return 1;
  }
  // Four crossings: an exit on face edge m pairs with the entry on edge m + 1
  // when the above corners connect through the middle, else with edge m - 1.
  *ambiguous = true;
  const bool connected = face_connects_above(g, f, degenerate);
  for (int s = 0; s < 2; ++s) {
    const int m = exit_slot[s];
    const int partner = connected ? (m + 1) % 4 : (m + 3) % 4;
    out[s] = {exits[s], edge_of[partner], f};
  }
  return 2;
}

// Follows segments end to start into closed loops.
void chain_segments(const Segment* segs, int n, CellPolygons& out) {
  int start_of[12];
  for (int e = 0; e < 12; ++e) start_of[e] = -1;
  for (int s = 0; s < n; ++s) start_of[segs[s].from_edge] = s;
  bool used[12] = {};
  for (int s0 = 0; s0 < n; ++s0) {
    if (used[s0]) continue;
    CellPolygon& poly = out.polygons[out.count++];
    int seen_faces = 0;
    for (int s = s0; !used[s]; s = start_of[segs[s].to_edge]) {
      used[s] = true;
      poly.edges[poly.size] = uint8_t(segs[s].from_edge);
      poly.faces[poly.size] = uint8_t(segs[s].face);
      ++poly.size;
      const int bit = 1 << segs[s].face;
      if ((seen_faces & bit) && (poly.double_face < 0 || segs[s].face < poly.double_face))
        poly.double_face = segs[s].face;
      seen_faces |= bit;
    }
  }
}

}  // namespace

bool face_connects_above(const double g[8], int f, bool* degenerate) {
  // With above corners p0, p2 and below corners p1, p3 (alternating around
  // the face), the bilinear saddle value minus alpha has the sign of
  // g(p0) g(p2) - g(p1) g(p3) (Theorem 3.3, the denominator being positive).
  // Products commute exactly in IEEE arithmetic, so every cell sharing the
  // face computes the same two numbers whatever its own corner order.
  const std::array<int, 4> q = cell::face_corners(f);
  const int a = g[q[0]] > 0 ? 0 : 1;
  const double above = g[q[a]] * g[q[a + 2]];
  const double below = g[q[1 - a]] * g[q[3 - a]];
  *degenerate = above == below;
  return above > below;
}

void cell_polygons(const double g[8], CellPolygons& out) {
  out = CellPolygons();
  Segment segs[12];
  int n = 0;
  for (int f = 0; f < 6; ++f) {
    bool ambiguous = false, degenerate = false;
    n += face_segments(g, f, segs + n, &ambiguous, &degenerate);
    out.ambiguous_faces += ambiguous;
    out.degenerate_saddles += degenerate;
    if (f % 2 == 0) {
      out.ambiguous_lower_faces += ambiguous;
      out.degenerate_lower_saddles += degenerate;
    }
  }
  chain_segments(segs, n, out);
}

const CellPolygons* unambiguous_cell_polygons(int above) {
  struct Table {
    CellPolygons cases[256];
    bool ambiguous[256];
    Table() {
      for (int c = 0; c < 256; ++c) {
        double g[8];
        for (int m = 0; m < 8; ++m) g[m] = (c >> m) & 1 ? 1.0 : -1.0;
        cell_polygons(g, cases[c]);
        ambiguous[c] = cases[c].ambiguous_faces > 0;
      }
    }
  };
  static const Table table;
  return table.ambiguous[above] ? nullptr : &table.cases[above];
}

double trilinear(const double g[8], double u, double v, double w) {
  const double x00 = g[0] + u * (g[1] - g[0]), x10 = g[2] + u * (g[3] - g[2]);
  const double x01 = g[4] + u * (g[5] - g[4]), x11 = g[6] + u * (g[7] - g[6]);
  const double y0 = x00 + v * (x10 - x00), y1 = x01 + v * (x11 - x01);
  return y0 + w * (y1 - y0);
}

namespace {

// Theorem 3.6 on one face f: the point where the perpendicular through the
// crossing of the face's asymptotes meets the contour.
bool extra_point_on_face(const double g[8], int f, std::array<double, 3>& uvw) {
  const int a = f / 2, b = (a + 1) % 3, c = (a + 2) % 3;
  // Bilinear values h[side][ub][uc] of the two faces perpendicular to a.
  double h[2][2][2];
  for (int corner = 0; corner < 8; ++corner) {
    const int x[3] = {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
    h[x[a]][x[b]][x[c]] = g[corner];
  }
  const int s = f % 2;
  const double d10 = h[s][1][0] - h[s][0][0], d01 = h[s][0][1] - h[s][0][0];
  const double d11 = h[s][1][1] - h[s][1][0] - h[s][0][1] + h[s][0][0];
  if (d11 == 0) return false;
  const double ub = -d01 / d11, uc = -d10 / d11;  // (3.8)
  auto bilinear = [&](int side) {
    const double x0 = h[side][0][0] + ub * (h[side][1][0] - h[side][0][0]);
    const double x1 = h[side][0][1] + ub * (h[side][1][1] - h[side][0][1]);
    return x0 + uc * (x1 - x0);
  };
  const double f0 = bilinear(0), f1 = bilinear(1);
  // NOTE: (3.11) with t measured from the face u_a = 0; a denominator that
  // vanishes relative to the values means the line runs along the contour.
  const double denom = f1 - f0;
  if (!(std::abs(denom) > 1e-12 * (std::abs(f0) + std::abs(f1)))) return false;
  const double t = -f0 / denom;
  // Remark 3.10: a point outside the cell is refused; so is one on a face
  // plane (t = 0 or 1 when the face's saddle value equals alpha), since
  // Theorem 3.5 needs the point off the plane of the face it fans over.
  if (!(t > 1e-6 && t < 1.0 - 1e-6)) return false;
  uvw[a] = t;
  uvw[b] = ub;
  uvw[c] = uc;
  return true;
}

}  // namespace

bool extra_point(const double g[8], const CellPolygon& polygon, std::array<double, 3>& uvw) {
  int count[6] = {0, 0, 0, 0, 0, 0};
  for (int i = 0; i < polygon.size; ++i) ++count[polygon.faces[i]];
  for (int f = 0; f < 6; ++f)
    if (count[f] >= 2 && extra_point_on_face(g, f, uvw)) return true;
  return false;
}

}  // namespace isoform
