// A mesh moved by an affine map: into another patient frame (RAS and LPS
// differ by a half turn about z, RAS and LAS by a mirror), or by any
// placement a caller wants.
#pragma once

#include "mesh.h"
#include "volume.h"

namespace isoform {

// Points (and precise points) by the map, normals by its inverse transpose
// (kept on the same side of the surface), and, where the map mirrors
// (negative determinant), every triangle's winding reversed with its
// neighbours, so the winding still agrees with the normals. Curvature is
// kept (directions turned) when the linear part is a rotation or mirror,
// and dropped otherwise, since a stretch changes it. Throws InvalidArgument
// for a map that is not finite or flattens space.
void transform_mesh(Mesh& mesh, const Affine& map);

}  // namespace isoform
