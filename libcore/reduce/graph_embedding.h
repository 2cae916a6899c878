// Beyond the seed: graph-mode inputs checked for what graph mode needs, and
// a cheap proof that such an input does not overlap itself, in place of the
// general check (mesh_overlap.h).
//
// Graph mode needs every triangle's (x, y) projection to turn
// counterclockwise (seen from +z, the normals up): a removal keeps each new
// triangle so (removal.h). A mesh whose projection is one-to-one cannot
// overlap itself: two triangles meeting in space beyond what they share would
// meet in the plane too. With every triangle counterclockwise, the projection
// is one-to-one when the boundary edges form one loop whose projection is a
// simple polygon: for a point of the plane off that polygon, the number of
// triangles whose projection holds it equals the polygon's winding number
// about it (the triangles' inner edges cancel), which is 0 or 1; so no two
// projections share an open set, and a vertex or edge touching a triangle it
// does not belong to would make them share one. The proof costs a pass over
// the boundary; the general check is a grid of every triangle's box
// (docs/reduce.md, "Graph inputs").
#pragma once

#include <string>

#include "../mesh.h"
#include "../vertex_stars.h"

namespace isoform::reduce {

// Throws InvalidArgument "<what>: ..." naming the first triangle whose
// projection is not certainly counterclockwise (clockwise, or vertical
// within rounding; edges shorter than about 1e-150 or longer than 1e150
// cannot be decided and are refused too). Every index must name a vertex
// (validate_indices).
void validate_graph(const Mesh& mesh, const std::string& what);

// True when the boundary is one loop whose projection is a simple polygon,
// decided exactly (orientation signs with a certain error bound; any
// uncertain pair of boundary edges gives false). False says nothing: the
// caller runs the general check. Uses the precise points when the mesh has
// them, as the general check does. The mesh must have passed
// validate_manifold (validate.h) with `stars`, and validate_graph.
bool projects_one_to_one(const Mesh& mesh, const VertexStars& stars);

}  // namespace isoform::reduce
