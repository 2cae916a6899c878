// The platelet of a grid point (Hamann 1991, Definition 4.12): the vertices
// of all tetrahedra of the six-tetrahedra split (Section 3.2, contour/tetra.h)
// that share the point, as index offsets from it.
#pragma once

#include <array>
#include <vector>

namespace isoform {

// The 14 offsets of the vertex star of the split that contour/tetra.cpp
// uses: the 6 axis neighbours, the face diagonals +-(-1,1,0), +-(-1,0,1),
// +-(0,-1,1) and the cell diagonal +-(-1,1,1). Derived from tetrahedra() once,
// in a fixed (sorted) order; centrally symmetric.
const std::vector<std::array<int, 3>>& graph_platelet_offsets();

}  // namespace isoform
