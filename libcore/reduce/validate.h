// What the reduction needs of its input, checked once at entry: finite
// coordinates, triangles of three distinct existing vertices, every edge in
// at most two triangles and in opposite directions when in two, and every
// vertex's triangles forming one fan. Each failure names the first offender.
#pragma once

#include <string>

#include "../mesh.h"

namespace isoform::reduce {

// Throws InvalidArgument "<what>: <problem>" for the first violation.
void validate_input(const Mesh& mesh, const std::string& what);

}  // namespace isoform::reduce
