// The curvature of one vertex: its frame, its platelet (widened where
// needed), the fit, and the fallbacks of vertex_curvature.h.
#pragma once

#include <vector>

#include "../mesh.h"
#include "principal.h"
#include "vertex_curvature.h"
#include "vertex_rings.h"

namespace isoform {

struct VertexFitScratch {
  RingScratch rings;
  std::vector<double> u, v, d;
};

struct VertexFitResult {
  PrincipalCurvatures curvature;  // zero curvature where flags say isolated or failed
  uint8_t flags = 0;
};

// extra_rings widens the method's platelet by that many rings everywhere.
VertexFitResult fit_vertex(const Mesh& mesh, const VertexRings& rings, int32_t vertex, CurvatureMethod method,
                           int extra_rings, VertexFitScratch& scratch);

}  // namespace isoform
