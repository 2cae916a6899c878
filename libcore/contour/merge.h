// Section 3.3's tables from per-brick tables: one global vertex table in
// which every crossing is kept once, shared by all the triangles that meet
// there; the triangle table; the neighbour table and the parts. Prefix sums
// place the bricks; only the keys of vertices on brick faces are sorted, and
// only edges on brick faces are matched globally (brick_topology.h).
#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <vector>

#include "../mesh.h"
#include "../progress.h"
#include "brick_contour.h"

namespace isoform {

// The contoured bricks of one grid and the storage of their tables.
struct BrickTables {
  std::vector<BrickMesh> bricks;  // the bricks that cross, in brick order
  tbb::enumerable_thread_specific<BrickStores> stores;
};

struct MergeOrientation {
  bool reverse = false;  // swap each triangle's last two vertices
  bool negate = false;   // normals point along minus the gradient
};

// Moves the bricks' vertices and triangles into mesh (points, normals as
// unit vectors along the gradients, zero where the gradient vanished,
// oriented triangles), fills mesh.neighbours, mesh.parts, mesh.part_count
// and mesh.stats as compute_topology (topology.h) would, and sums the
// bricks' stats into mesh.contour. Frees the bricks as it goes. Returns
// true when some normal is zero. Runs in parallel with TBB in the calling
// task arena; the result does not depend on the number of threads.
bool merge_bricks(BrickTables& tables, const MergeOrientation& orientation, Mesh& mesh,
                  const Progress& progress);

}  // namespace isoform
