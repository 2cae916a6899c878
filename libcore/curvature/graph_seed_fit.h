// The seed's curvature estimate at a grid point (Hamann 1991, Section 4.3,
// steps (i)-(viii)): the platelet in the six-tetrahedra split, the tangent
// space from an estimated normal, signed distances and local coordinates,
// the 6x6 normal equations (4.47, 4.48) for the osculating quadric, and the
// eigenvalues of its symmetric coefficient matrix (Theorem 4.7).
#pragma once

#include <array>

#include "graph_principal.h"
#include "graph_samples.h"

namespace isoform {

// The world gradient of f at the point from the grid, which the seed leaves
// open: central differences in index space, second-order one-sided
// differences (-3 f0 + 4 f1 - f2) / 2 where one side is undefined, first
// order where only one neighbour is, mapped to world by the inverse
// transpose of the grid map. False when an axis has no defined neighbour.
bool graph_grid_gradient(const GraphSamples& s, const GraphAxes& axes, std::array<double, 3>& g);

struct GraphSeedFit {
  bool ok = false;       // false: fewer than 6 platelet points or U^T U ill-conditioned
  int points = 0;        // platelet points used (14 inside the data)
  GraphPrincipal curvature;
};

// The fit for a point where f has world gradient g (from graph_grid_gradient,
// or exact in tests). Only defined platelet points are used, so at the data's
// edge the platelet is one-sided. NOTE: 4.47 prints U c = d with rows
// (u^2, 2uv, 2uw, v^2, 2vw, w^2) but the quadric it fits is 4.49, which has a
// factor 1/2; Theorem 4.7 reads c as the Hessian, so the rows here carry the
// 1/2 (literally, 4.47 would halve every curvature).
GraphSeedFit graph_seed_fit(const GraphSamples& s, const GraphAxes& axes, const std::array<double, 3>& g);

}  // namespace isoform
