// The cell method of Section 3.2 on single cells: all 256 sign cases with both
// decider outcomes on every ambiguous face, agreement of neighbouring cells on
// their shared face, and the extra point of Figure 3.5.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <tuple>

#include "libcore/contour/cell_polygons.h"
#include "libcore/contour/cell_table.h"

using namespace isoform;

namespace {

using SegmentSet = std::set<std::pair<int, int>>;

SegmentSet segments_on_face(const CellPolygons& cp, int face) {
  SegmentSet out;
  for (int p = 0; p < cp.count; ++p) {
    const CellPolygon& poly = cp.polygons[p];
    for (int i = 0; i < poly.size; ++i)
      if (poly.faces[i] == face) out.insert({poly.edges[i], poly.edges[(i + 1) % poly.size]});
  }
  return out;
}

// The edge of the neighbour across the face normal to axis a that coincides
// with edge e of this cell.
int mirror_edge(int e, int a) {
  const std::array<int, 2> c = cell::edge_corners(e);
  return cell::edge_between(c[0] ^ (1 << a), c[1] ^ (1 << a));
}

void random_cell(int signs, std::mt19937& rng, double g[8]) {
  std::uniform_real_distribution<double> mag(0.05, 1.0);
  for (int c = 0; c < 8; ++c) g[c] = (signs >> c & 1) ? mag(rng) : -mag(rng);
}

void check_polygons(const double g[8], const CellPolygons& cp) {
  // Every crossing edge is a point of exactly one polygon, once.
  int uses[12] = {};
  for (int p = 0; p < cp.count; ++p) {
    const CellPolygon& poly = cp.polygons[p];
    ASSERT_GE(poly.size, 3);
    ASSERT_LE(poly.size, 12);
    ASSERT_NE(poly.size, 10);
    ASSERT_NE(poly.size, 11);
    int per_face[6] = {};
    for (int i = 0; i < poly.size; ++i) {
      ++uses[poly.edges[i]];
      ++per_face[poly.faces[i]];
    }
    const bool has_double = *std::max_element(per_face, per_face + 6) >= 2;
    EXPECT_EQ(has_double, poly.double_face >= 0);
  }
  for (int e = 0; e < 12; ++e) {
    const std::array<int, 2> c = cell::edge_corners(e);
    EXPECT_EQ(uses[e], (g[c[0]] > 0) != (g[c[1]] > 0) ? 1 : 0) << "edge " << e;
  }
}

// Builds the neighbour across face f, sharing the face's four values, and
// checks that both cells draw the same segments there, traversed oppositely.
void check_neighbour_agrees(const double g[8], const CellPolygons& cp, int f, std::mt19937& rng) {
  const int a = f / 2, s = f % 2;
  double h[8];
  random_cell(rng() & 255, rng, h);
  for (int c = 0; c < 8; ++c)
    if (((c >> a) & 1) == s) h[c ^ (1 << a)] = g[c];
  CellPolygons other;
  cell_polygons(h, other);
  SegmentSet mine;
  for (const auto& seg : segments_on_face(cp, f))
    mine.insert({mirror_edge(seg.second, a), mirror_edge(seg.first, a)});
  EXPECT_EQ(mine, segments_on_face(other, 2 * a + (1 - s)));
}

}  // namespace

TEST(CellPolygons, AllSignCasesBothDeciderOutcomesAndNeighboursAgree) {
  std::mt19937 rng(1991);
  for (int signs = 0; signs < 256; ++signs) {
    std::set<std::pair<int, bool>> outcomes;  // (face, connected)
    std::set<int> ambiguous;
    for (int draw = 0; draw < 96; ++draw) {
      double g[8];
      random_cell(signs, rng, g);
      CellPolygons cp;
      cell_polygons(g, cp);
      check_polygons(g, cp);
      for (int f = 0; f < 6; ++f) {
        const std::array<int, 4> q = cell::face_corners(f);
        const bool amb = (g[q[0]] > 0) == (g[q[2]] > 0) && (g[q[1]] > 0) == (g[q[3]] > 0) &&
                         (g[q[0]] > 0) != (g[q[1]] > 0);
        if (amb) {
          bool degenerate;
          ambiguous.insert(f);
          outcomes.insert({f, face_connects_above(g, f, &degenerate)});
        }
        check_neighbour_agrees(g, cp, f, rng);
      }
      if (::testing::Test::HasFailure()) return;
    }
    for (int f : ambiguous) {
      EXPECT_TRUE(outcomes.count({f, true})) << "case " << signs << " face " << f;
      EXPECT_TRUE(outcomes.count({f, false})) << "case " << signs << " face " << f;
    }
  }
}

TEST(CellPolygons, DegenerateSaddleTakesTheAdHocRule) {
  // All magnitudes equal: every ambiguous face has its saddle exactly at the
  // isovalue; the seed's rule cuts off the above corners.
  for (int signs = 0; signs < 256; ++signs) {
    double g[8];
    for (int c = 0; c < 8; ++c) g[c] = (signs >> c & 1) ? 1.0 : -1.0;
    CellPolygons cp;
    cell_polygons(g, cp);
    check_polygons(g, cp);
    for (int f = 0; f < 6; ++f) {
      bool degenerate = false;
      const std::array<int, 4> q = cell::face_corners(f);
      const bool amb = (g[q[0]] > 0) == (g[q[2]] > 0) && (g[q[1]] > 0) == (g[q[3]] > 0) &&
                       (g[q[0]] > 0) != (g[q[1]] > 0);
      if (!amb) continue;
      EXPECT_FALSE(face_connects_above(g, f, &degenerate));
      EXPECT_TRUE(degenerate);
    }
  }
  // The checkerboard cell: six ambiguous faces, all degenerate, and four
  // separate triangles around the above corners.
  double g[8];
  for (int c = 0; c < 8; ++c) g[c] = ((c & 1) ^ ((c >> 1) & 1) ^ (c >> 2)) ? -1.0 : 1.0;
  CellPolygons cp;
  cell_polygons(g, cp);
  EXPECT_EQ(cp.ambiguous_faces, 6);
  EXPECT_EQ(cp.degenerate_saddles, 6);
  EXPECT_EQ(cp.count, 4);
  for (int p = 0; p < cp.count; ++p) EXPECT_EQ(cp.polygons[p].size, 3);
}

TEST(CellPolygons, PolygonSizesAndExtraPoints) {
  // Over random cells of the checkerboard and the other many-crossing cases,
  // polygons of 3..9 and 12 points occur, never 10 or 11 (no sign pattern
  // of the eight corners makes one), and every polygon of 7 or more points
  // has two segments on one face.
  std::mt19937 rng(7);
  std::set<int> sizes;
  for (int signs = 0; signs < 256; ++signs)
    for (int draw = 0; draw < 200; ++draw) {
      double g[8];
      random_cell(signs, rng, g);
      CellPolygons cp;
      cell_polygons(g, cp);
      for (int p = 0; p < cp.count; ++p) {
        sizes.insert(cp.polygons[p].size);
        if (cp.polygons[p].size >= 7) {
          EXPECT_GE(cp.polygons[p].double_face, 0);
        }
      }
    }
  EXPECT_EQ(sizes, (std::set<int>{3, 4, 5, 6, 7, 8, 9, 12}));
}

TEST(CellPolygons, Figure35ExtraPointLiesOnTheTrilinearContour) {
  // f of Figure 3.5 at the corners (u | v << 1 | w << 2); f(1,1,0) = 0.
  const double f[8] = {2.0, 1.6, 1.4, 0.0, 1.4, 0.4, 2.0, 2.0};
  double g[8];
  for (int c = 0; c < 8; ++c) g[c] = f[c] - 1.5;
  CellPolygons cp;
  cell_polygons(g, cp);
  int with_extra = 0;
  for (int p = 0; p < cp.count; ++p) {
    if (cp.polygons[p].double_face < 0) continue;
    ++with_extra;
    std::array<double, 3> uvw;
    ASSERT_TRUE(extra_point(g, cp.polygons[p], uvw));
    for (double x : uvw) {
      EXPECT_GE(x, 0.0);
      EXPECT_LE(x, 1.0);
    }
    EXPECT_NEAR(trilinear(f, uvw[0], uvw[1], uvw[2]), 1.5, 1e-12);
  }
  EXPECT_EQ(with_extra, 1);
}
