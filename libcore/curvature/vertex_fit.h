// The curvature of one vertex: its frame, its platelet (widened where
// needed), the fit, and the fallbacks of vertex_curvature.h.
#pragma once

#include <vector>

#include "../mesh.h"
#include "principal.h"
#include "vertex_curvature.h"
#include "vertex_rings.h"

namespace isoform {

// The local coordinates and heights of one platelet.
struct PlateletPoints {
  std::vector<double> u, v, d;
};

struct VertexFitScratch {
  RingScratch rings;
  PlateletPoints points;
  PlateletPoints lanes[2];    // fit_vertices: each group's four platelets side by side (fit_height_lanes)
  RingList lane_rings[2][4];  // fit_vertices: each group's four platelets' vertices
};

struct VertexFitResult {
  PrincipalCurvatures curvature;  // zero curvature where flags say isolated or failed
  uint8_t flags = 0;
};

// extra_rings widens the method's platelet by that many rings everywhere.
VertexFitResult fit_vertex(const Mesh& mesh, const VertexRings& rings, int32_t vertex, CurvatureMethod method,
                           int extra_rings, VertexFitScratch& scratch);

// fit_vertex for the vertices first .. first + count - 1 (count 1 to 8) into
// out: the same results, bit for bit. Their first fits (the method's model
// on its platelet, which nearly every vertex keeps) run side by side, in
// groups of four (fit_height_lanes); a vertex that needs more goes through
// fit_vertex.
void fit_vertices(const Mesh& mesh, const VertexRings& rings, int32_t first, int count, CurvatureMethod method,
                  int extra_rings, VertexFitScratch& scratch, VertexFitResult (&out)[8]);

}  // namespace isoform
