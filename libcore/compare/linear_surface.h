// The flat base triangles as a TriangleSurface: the comparison study's
// third column, the surface a renderer shows when it draws the mesh as is.
#pragma once

#include <memory>

#include "libcore/mesh.h"
#include "libcore/surface.h"

namespace isoform::compare {

// Keeps a reference to mesh, which must outlive the surface. Second
// derivatives are exactly zero (has_second is set); degenerate triangles
// have no normal and evaluate to false.
std::unique_ptr<TriangleSurface> make_linear_surface(const Mesh& mesh);

}  // namespace isoform::compare
