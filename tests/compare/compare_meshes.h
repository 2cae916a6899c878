// Small meshes made in code for the comparison tests, with their topology
// (neighbours, parts) filled and double-precision points kept.
#pragma once

#include <array>

#include "libcore/mesh.h"

namespace isoform::test {

// The octahedron with vertices +-e_i (on the unit sphere), outward triangles.
Mesh octahedron();
// The icosahedron inscribed in the unit sphere; jitter > 0 moves each vertex
// by a fixed pseudo-random offset of up to jitter, so no two limit points
// coincide by symmetry.
Mesh icosahedron(double jitter = 0.0);
// A torus of m x n vertices (major radius R, minor r), each quad split along
// the same diagonal: every vertex has valence 6, so its Loop limit is made
// of regular box-spline patches only.
Mesh regular_torus(int m, int n, double R, double r);

std::array<double, 3> vertex(const Mesh& mesh, int v);

}  // namespace isoform::test
