// Inputs for the side-vertex patch tests, made in code.
#pragma once

#include "libcore/mesh.h"

namespace isoform::patch::test {

// A regular tetrahedron inscribed in the unit sphere (Figure 6.7), outward
// winding, with the sphere's normals (= the points).
Mesh tetrahedron();
// An icosahedron in the unit sphere, outward winding, sphere normals.
Mesh icosahedron();
// A closed mesh whose normals are not the sphere's: an octahedron scaled
// (1, 0.7, 1.3) with normals of the ellipsoid through its vertices, turned
// by a fixed pseudo-random angle, so edges see skew, unequal normals.
Mesh skewed_octahedron();

}  // namespace isoform::patch::test
