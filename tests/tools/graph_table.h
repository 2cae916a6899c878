// Table 4.2 of Hamann (1991): the trivariate test functions of Section 4.3
// on the seed's 26^3 grid over [-1, 1]^3 (spacing 1/12.5), their exact graph
// curvatures, and the RMS errors of H and K of a method against them. Shared
// by the tool that writes docs/curvature-volume.md and the test that guards
// the figures.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "libcore/curvature/graph_point.h"

namespace isoform::table42 {

struct Function {
  std::string name;  // as the seed prints it
  double (*value)(double x, double y, double z);
  // gradient (3) then Hessian upper triangle xx, xy, xz, yy, yz, zz (6)
  void (*derivatives)(double x, double y, double z, double out[9]);
};

// The five functions in the seed's order: linear, q1, q2, cubic, cosine.
const std::vector<Function>& functions();

enum class Column {
  Default,           // isoform's default method (graph_jet_fit)
  Seed,              // the seed's method, gradient from the grid
  SeedExactGradient  // the seed's method with the analytic gradient
};

struct Errors {
  double rms_mean_all = 0, rms_gauss_all = 0;            // over all 26^3 points
  double rms_mean_interior = 0, rms_gauss_interior = 0;  // over the 24^3 inner points
  std::array<long long, kGraphFitCount> fits{};
};

// The errors of one column on one function, in double precision samples.
Errors measure(const Function& f, Column column);

// Points per axis of the seed's grid.
constexpr int kGridPoints = 26;

}  // namespace isoform::table42
