// One grid point: the method's fit, then its fallbacks (graph_point.h).
#include "graph_point.h"

#include "graph_jet_fit.h"
#include "graph_platelet.h"
#include "graph_seed_fit.h"

namespace isoform {
namespace {

bool try_jet(const GraphSamples& s, const GraphAxes& axes, GraphCurvature& out) {
  const GraphJetFit jet = graph_jet_fit(s, axes);
  switch (jet.kind) {
    case GraphJetKind::Centred: out.fit = GraphFit::JetCentred; break;
    case GraphJetKind::Shifted: out.fit = GraphFit::JetShifted; break;
    case GraphJetKind::Reduced: out.fit = GraphFit::JetReduced; break;
    case GraphJetKind::Failed: return false;
  }
  out.curvature = jet.curvature;
  return true;
}

bool try_seed(const GraphSamples& s, const GraphAxes& axes, const std::array<double, 3>& g, GraphCurvature& out) {
  const GraphSeedFit seed = graph_seed_fit(s, axes, g);
  if (!seed.ok) return false;
  out.curvature = seed.curvature;
  out.fit = seed.points == int(graph_platelet_offsets().size()) ? GraphFit::Platelet : GraphFit::PlateletPartial;
  return true;
}

bool try_seed(const GraphSamples& s, const GraphAxes& axes, GraphCurvature& out) {
  std::array<double, 3> g;
  return graph_grid_gradient(s, axes, g) && try_seed(s, axes, g, out);
}

}  // namespace

GraphCurvature graph_curvature_at(const GraphSamples& s, const GraphAxes& axes, GraphMethod method) {
  GraphCurvature out;
  if (method == GraphMethod::Seed) {
    if (!try_seed(s, axes, out)) try_jet(s, axes, out);
  } else {
    if (!try_jet(s, axes, out)) try_seed(s, axes, out);
  }
  return out;
}

GraphCurvature graph_seed_curvature_with_gradient(const GraphSamples& s, const GraphAxes& axes,
                                                  const std::array<double, 3>& g) {
  GraphCurvature out;
  if (!try_seed(s, axes, g, out)) try_jet(s, axes, out);
  return out;
}

}  // namespace isoform
