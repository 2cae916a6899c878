// What the reduction needs of its input, checked once at entry: finite
// coordinates, triangles of three distinct existing vertices, every edge in
// at most two triangles and in opposite directions when in two, every
// vertex's triangles forming one fan, and no two triangles intersecting
// beyond the vertices they share (mesh_overlap.h). Each failure names the
// first offender.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "../mesh.h"
#include "../vertex_stars.h"

namespace isoform::reduce {

// One violation, and what it involves (indices into the input).
struct Offence {
  std::string problem;   // e.g. "the mesh is not manifold: edge (0, 1) is shared by 3 triangles"
  int32_t triangle = -1; // a triangle it involves, or -1
  int32_t other = -1;    // a second triangle (an overlap), or -1
  int32_t vertex = -1;   // a vertex all of whose triangles are involved, or -1
};

// Calls sink with each violation, the checks in the order above (all of one
// check before the next); stops when sink returns false. Throws
// InvalidArgument "<what>: ..." for an index that names no vertex.
void find_offences(const Mesh& mesh, const std::string& what, const std::function<bool(const Offence&)>& sink);

// Throws InvalidArgument "<what>: <problem>" for the first violation.
void validate_input(const Mesh& mesh, const std::string& what);

// The same in steps: validate_indices, then every check but the overlap one
// (after it the mesh is a manifold, consistently oriented triangulation with
// finite points, so work that is local to each vertex may start), reading
// the star table (vertex_stars.h) that the caller may use again, then the
// overlap check. validate_input is these three. The overlap check needs
// only validate_indices before it (it may run beside validate_manifold; on a
// mesh that fails the latter its result means nothing).
// validate_manifold may also say which vertices lie on the boundary (one of
// their edges in one triangle): *on_boundary gets a flag per vertex, or
// stays empty when the check could not tell (then compute them).
void validate_manifold(const Mesh& mesh, const VertexStars& stars, const std::string& what,
                       std::vector<uint8_t>* on_boundary = nullptr);
void validate_no_overlap(const Mesh& mesh, const std::string& what);
// Throws InvalidArgument "<what>: ..." for a triangle index that names no vertex.
void validate_indices(const Mesh& mesh, const std::string& what);

}  // namespace isoform::reduce
