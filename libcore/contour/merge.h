// Section 3.3's global vertex table from per-brick tables: every crossing is
// kept once, shared by all the triangles that meet there. Prefix sums place
// the bricks; only the keys of vertices on brick faces are sorted.
#pragma once

#include <vector>

#include "../mesh.h"
#include "brick_contour.h"

namespace isoform {

// Moves the bricks' vertices and triangles into mesh (points, normals as
// unit vectors along the gradients, triangles) and sums their stats into
// mesh.contour. Runs in parallel with TBB in the calling task arena.
void merge_bricks(std::vector<BrickMesh>& bricks, Mesh& mesh);

}  // namespace isoform
