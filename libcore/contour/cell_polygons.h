// The trilinear-consistent cell method of Hamann (1991), Section 3.2: the
// closed contour polygons of one cell, and the extra point of Theorem 3.6.
//
// Input is g = f - alpha at the 8 corners (cell_table.h order), with no zero
// (Remark 3.8: the caller has already moved samples equal to alpha). A corner
// is "above" when g > 0.
#pragma once

#include <array>
#include <cstdint>

namespace isoform {

struct CellPolygon {
  int size = 0;              // 3..12 points
  std::array<uint8_t, 12> edges{};  // the edge of each point, in loop order
  std::array<uint8_t, 12> faces{};  // the face of the segment leaving point i
  // The first face (lowest index) that holds two segments of this polygon,
  // or -1. Such a polygon needs the extra point (Theorem 3.4 (ii), 3.5).
  int double_face = -1;
};

struct CellPolygons {
  int count = 0;
  std::array<CellPolygon, 6> polygons;
  int ambiguous_faces = 0;     // faces with four crossings
  int degenerate_saddles = 0;  // of those, saddle value exactly alpha
  int ambiguous_lower_faces = 0, degenerate_lower_saddles = 0;  // on faces s = 0 only
};

// Builds the polygons. Segments on each face are directed so that the above
// region lies to their left seen from outside the cell; chained, each polygon
// winds counter-clockwise seen from the above side (its normal points toward
// increasing f). Ambiguous faces use the asymptotic decider (Theorem 3.3),
// evaluated from the face's four values by products that do not depend on
// which cell asks, so both cells sharing a face decide alike.
void cell_polygons(const double g[8], CellPolygons& out);

// The polygons of the cells with corner signs `above` (bit c set when
// g[c] > 0) when none of their faces is ambiguous: those depend on the signs
// alone and come from a table made once. nullptr when some face has four
// crossings; cell_polygons() must then decide it.
const CellPolygons* unambiguous_cell_polygons(int above);

// True when face f's four crossings are joined through the face's middle
// (the above corners connected): the saddle value exceeds alpha. A saddle
// equal to alpha takes the seed's ad-hoc rule: the segments cut off the above
// corners (not connected). *degenerate reports that tie.
bool face_connects_above(const double g[8], int f, bool* degenerate);

// The extra point of Theorem 3.6 for a polygon with a double face, in
// cell coordinates (u, v, w): on the line through the face's asymptote
// crossing (3.8) perpendicular to the face, where the trilinear interpolant
// equals alpha (3.11). Faces with two segments are tried in index order; a
// point outside the cell (Remark 3.10) or a vanishing denominator moves on to
// the next face. Returns false when none works: the caller then uses the
// centroid of the polygon's points (Remark 3.9), which is always inside.
bool extra_point(const double g[8], const CellPolygon& polygon, std::array<double, 3>& uvw);

// The trilinear interpolant of g at (u, v, w) in [0, 1]^3.
double trilinear(const double g[8], double u, double v, double w);

}  // namespace isoform
