// isoform's default curvature estimate at a grid point: a least-squares
// polynomial fit of f itself over a box of samples (a jet), then the exact
// curvature of the fitted polynomial's graph by 4.36.
//
// The seed fits a quadric in the 4-D tangent space of an estimated normal on
// the 14-point platelet; its error comes from the normal (gradient) estimate
// and, at the data's edge, from a one-sided platelet. Fitting f over the
// grid instead keeps the linear terms (the gradient comes from the same fit,
// so there is no separate normal error), reproduces every polynomial of the
// fitted degree exactly, and at the data's edge shifts the box inward rather
// than shrinking it.
#pragma once

#include "graph_principal.h"
#include "graph_samples.h"

namespace isoform {

enum class GraphJetKind {
  Centred,   // degree 6 on the full 7x7x7 box centred at the point
  Shifted,   // degree 6 (at most n - 1 along an axis with n < 7 samples) on a full box
             // moved or cut where the defined samples end
  Reduced,   // degree 2 on the defined samples of a box with holes
  Failed     // an axis has fewer than 3 samples in a row, or the fit is singular
};

struct GraphJetFit {
  GraphJetKind kind = GraphJetKind::Failed;
  GraphPrincipal curvature;
};

// The box: along each axis the run of defined samples through the point
// (up to kGraphReach each way) gives 7 samples, centred when the run
// allows, else moved inward; a run of n = 3..6 gives n and caps the degree
// along the axis at n - 1. Full boxes use operators computed once
// per box shape (thread-safe); boxes with holes solve per point.
GraphJetFit graph_jet_fit(const GraphSamples& s, const GraphAxes& axes);

}  // namespace isoform
