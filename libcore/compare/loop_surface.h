// The Loop limit surface of a triangle mesh (Loop 1987), evaluated with
// OpenSubdiv as the baseline of the comparison study. This module is the only
// place isoform uses OpenSubdiv: it is a baseline, not part of the pipeline.
//
// The mesh is refined adaptively around its irregular vertices (valence other
// than 6, boundaries) up to `isolation` levels; regular regions become quartic
// box-spline patches, the rest Gregory triangle end caps. Every base triangle
// is one parametric face of OpenSubdiv, whose corners (0,0), (1,0), (0,1) are
// its vertices t0, t1, t2: the (u, v) of surface.h. In the Gregory end caps
// OpenSubdiv's derivatives are approximate (exact first derivatives only at
// the base vertices), so samples there come without second derivatives
// (has_second false).
#pragma once

#include <memory>
#include <string>

#include "libcore/mesh.h"
#include "libcore/surface.h"

namespace isoform::compare {

struct LoopOptions {
  // Adaptive isolation of irregular features, 1..10: the Gregory end caps
  // shrink by half per level (and the patch count grows linearly).
  int isolation = 6;
  // Boundary rule: true (default) interpolates boundary edges as cubic
  // B-splines and keeps valence-2 boundary vertices as corners (OpenSubdiv's
  // VTX_BOUNDARY_EDGE_AND_CORNER); false smooths corners (EDGE_ONLY).
  bool sharp_corners = true;
};

// Builds the surface; nullptr and a message in `error` when the mesh cannot
// be refined (no triangles, indices out of range, a topology OpenSubdiv
// refuses). OpenSubdiv's own error reports end up in `error`, never printed.
std::unique_ptr<TriangleSurface> make_loop_surface(const Mesh& mesh, const LoopOptions& options,
                                                   std::string& error);

}  // namespace isoform::compare
