// The curvature of the graph of f at one grid point, by a named method, with
// the fit that was actually used.
#pragma once

#include <array>

#include "graph_principal.h"
#include "graph_samples.h"

namespace isoform {

enum class GraphMethod {
  Default = 0,  // graph_jet_fit, falling back to the seed's platelet fit
  Seed = 1      // graph_seed_fit with the grid gradient, falling back to the jet
};

// Which fit gave a point's curvature; the C API's ISOFORM_GRAPH_FIT_* values.
enum class GraphFit {
  JetCentred = 0,      // degree-6 fit on the centred 7x7x7 box
  JetShifted = 1,      // degree-6 fit on a box moved or cut at the data's edge
  JetReduced = 2,      // degree-2 fit on a box with holes
  Platelet = 3,        // the seed's fit on the full 14-point platelet
  PlateletPartial = 4, // the seed's fit on a one-sided platelet
  None = 5             // nothing could be fitted: all results 0
};
constexpr int kGraphFitCount = 6;

struct GraphCurvature {
  GraphPrincipal curvature;
  GraphFit fit = GraphFit::None;
};

// The curvature at the point of s (its own sample must be defined).
GraphCurvature graph_curvature_at(const GraphSamples& s, const GraphAxes& axes, GraphMethod method);

// The seed's method with a gradient the caller gives: for the Table 4.2
// tool's "exact gradient" column only (real data have no exact gradient).
GraphCurvature graph_seed_curvature_with_gradient(const GraphSamples& s, const GraphAxes& axes,
                                                  const std::array<double, 3>& g);

}  // namespace isoform
