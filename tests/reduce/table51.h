// Table 5.1 of Hamann (1991): the nine functions of Table 4.1 on the seed's
// 51 x 51 grid over [-1, 1]^2, reduced by 50, 80 and 90 %, and the RMS error
// (5.41) of the reduced piecewise linear function at the original knots.
// Shared by the tool that writes docs/reduce.md and the test that guards it.
#pragma once

#include <array>

#include "libcore/mesh.h"
#include "libcore/reduce/reduce.h"
#include "tests/curvature/truth.h"

namespace isoform::table51 {

// The seed's row of Table 5.1 for graph g of Table 4.1 (same order).
std::array<double, 3> seed_row(int function);

// The reduction fractions of the table's columns: 50, 80, 90 % removed.
constexpr double kRemoved[3] = {0.5, 0.8, 0.9};

// RMS (5.41) at the knots of `original` (a graph mesh) of the piecewise
// linear function of `reduced`; a knot outside every reduced triangle counts
// as an error of +infinity (the domain must stay covered).
double knot_rms(const Mesh& original, const Mesh& reduced);

struct Result {
  double rms = 0;
  ReduceStats stats;
  long long triangles_after = 0;
};

// Reduces graph g's mesh by `removed` in graph mode with `options`' other
// fields, and measures it.
Result measure(const truth::Graph& g, double removed, ReduceOptions options = {});

}  // namespace isoform::table51
