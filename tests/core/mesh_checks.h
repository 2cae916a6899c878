// Shared helpers for libcore tests: analytic dense fields and mesh checks.
#pragma once

#include <functional>
#include <memory>

#include "libcore/contour/contour.h"
#include "libcore/mesh.h"
#include "libcore/volume.h"

namespace isoform::test {

// A dense grid of f(i, j, k) sampled at integer points 0..n-1 per axis.
std::shared_ptr<const ScalarGrid> dense_grid(const Index3& n, const std::function<double(int, int, int)>& f,
                                             GridClass cls = GridClass::Other);
// A dense grid from explicit samples, x fastest.
std::shared_ptr<const ScalarGrid> dense_grid(const Index3& n, std::vector<float> values,
                                             GridClass cls = GridClass::Other);

Mesh run_contour(const ScalarGrid& grid, double iso, ContourMethod method = ContourMethod::Cells,
                 int threads = 0);

// Edges used by exactly one triangle whose end points do not both lie on the
// same face plane of the box [0, n-1]^3 (index space = world space here).
long long interior_boundary_edges(const Mesh& mesh, const Index3& n);

// Trilinear interpolant of a dense field at a point in index space.
double trilinear_at(const std::vector<float>& v, const Index3& n, double x, double y, double z);

}  // namespace isoform::test
