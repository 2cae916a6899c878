// Normals for meshes that arrive without a volume (Remark 3.15 of Hamann
// 1991): at each vertex, a least-squares quadratic height field over the
// one-ring in a local frame; the frame's axis is re-aimed at the fitted
// graph's normal and the fit repeated, which lowers the residual the remark
// asks to minimise. Orientation follows the triangles' winding.
#pragma once

#include "mesh.h"

namespace isoform {

// Fills mesh.normals (unit length) from mesh.points and mesh.triangles.
// Vertices with too few neighbours for the quadratic use a plane fit, and
// isolated vertices get (0, 0, 1).
void estimate_normals(Mesh& mesh);

}  // namespace isoform
