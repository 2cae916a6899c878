// The platelet of a grid point, derived from the tetrahedra of a cell.
#include "graph_platelet.h"

#include <algorithm>

#include "../contour/tetra.h"

namespace isoform {
namespace {

std::array<int, 3> corner(int c) { return {c & 1, (c >> 1) & 1, (c >> 2) & 1}; }

// A grid point is corner c of the cell whose lower corner lies at -corner(c)
// from it; every other corner of a tetrahedron of that cell holding c is a
// platelet point. The split is the same in every cell, so this covers the
// point's whole vertex star.
std::vector<std::array<int, 3>> derive_offsets() {
  std::vector<std::array<int, 3>> out;
  for (const auto& tet : tetrahedra())
    for (int c : tet)
      for (int d : tet) {
        if (d == c) continue;
        const auto pc = corner(c), pd = corner(d);
        out.push_back({pd[0] - pc[0], pd[1] - pc[1], pd[2] - pc[2]});
      }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

const std::vector<std::array<int, 3>>& graph_platelet_offsets() {
  static const std::vector<std::array<int, 3>> offsets = derive_offsets();
  return offsets;
}

}  // namespace isoform
