// Dropping a mesh's small parts: the specks of a noisy scan's contour, by
// their triangle count or the volume they enclose, or all but the largest.
#pragma once

#include "mesh.h"

namespace isoform {

struct PartFilter {
  long long min_triangles = 0;  // drop parts of fewer triangles; 0 keeps all
  double min_volume = 0.0;      // drop closed parts enclosing less (world units³); 0 keeps all
  long long largest = 0;        // keep only the K parts of most triangles; 0 keeps all
};

struct PartFilterResult {
  long long parts_before = 0, parts_after = 0;
  long long triangles_before = 0, triangles_after = 0;
};

// The volume a closed part encloses, by the divergence theorem over its
// triangles (as a positive number whichever way they face); -1 for a part
// with a boundary or non-manifold edge, whose volume is not defined. One
// entry per part. Needs mesh.neighbours and mesh.parts.
std::vector<double> part_volumes(const Mesh& mesh);

// Removes the parts the filter drops, with the vertices only they used;
// per-vertex data (normals, colours, curvature) follow the kept vertices.
// Neighbours, parts (renumbered, largest first) and stats are computed
// again. A part is kept when it passes every test set; a part with no
// defined volume passes the volume test.
PartFilterResult filter_parts(Mesh& mesh, const PartFilter& filter);

}  // namespace isoform
