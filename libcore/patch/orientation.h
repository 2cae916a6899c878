// Where the side-vertex surface folds over. The construction makes
// neighbouring patches share the tangent plane along every edge (Theorem
// 6.2), but not its orientation: over a triangle whose data normals point
// against its winding (an inverted triangle, which contours of thin or noisy
// structures contain), or next to an edge whose normals turn sharply, a patch
// can meet its neighbour with du x dv reversed. The shared plane is then the
// same and the oriented normals differ by pi: the surface folds back along
// the edge. No choice of curves can remove that from such data (the patch
// interpolates the data and its orientation is the triangle's), so the
// folds are found and reported instead.
#pragma once

#include <cstdint>
#include <vector>

#include "side_vertex_surface.h"

namespace isoform::patch {

struct FoldReport {
  long long inverted_triangles = 0;  // face normal against the sum of its vertex normals
  long long folded_edges = 0;        // edges whose incident patches disagree in orientation
  std::vector<int32_t> edges;        // those edges (SideVertexSurface edge indices), ascending
};

// Evaluates each patch at `samples` points along each of its edges and
// compares du x dv with the edge's boundary normal n_S: an edge is folded
// when one incident patch agrees with n_S there and another does not (a fold,
// or a winding that differs between the two triangles).
FoldReport find_folds(const SideVertexSurface& s, int samples = 3);

// True when the triangle's face normal points against the sum of its vertex
// normals.
bool inverted_triangle(const SideVertexSurface& s, size_t triangle);

}  // namespace isoform::patch
