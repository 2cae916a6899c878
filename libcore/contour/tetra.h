// The six-tetrahedra split of a cell (Hamann 1991, Section 3.2), with the
// contour of the linear interpolant on each tetrahedron.
//
// The split uses the diagonal from corner (1,0,0) to (0,1,1) and, on every
// face, the diagonal from (p=1, q=0) to (p=0, q=1) in the face's two axes
// p < q. Opposite faces carry parallel diagonals, so neighbouring cells share
// their face diagonals and the tetrahedral mesh is conforming.
#pragma once

#include <array>
#include <cstdint>

namespace isoform {

// The contour polygon of a tetrahedron: a triangle or a planar convex
// quadrilateral, as corner pairs (cell corner ids, cell_table.h order), each
// pair an edge of the tetrahedron whose end points lie on either side of the
// contour. The cyclic order makes the normal point toward the above (g > 0)
// side.
struct TetPolygon {
  int size = 0;  // 0, 3 or 4
  std::array<std::array<uint8_t, 2>, 4> edges{};
};

// The six tetrahedra as cell corner ids, as printed in the seed.
const std::array<std::array<int, 4>, 6>& tetrahedra();

// The contour polygon of tetrahedron t for the sign pattern `above` (bit m
// set when its m-th corner has g > 0).
const TetPolygon& tet_polygon(int t, int above);

}  // namespace isoform
