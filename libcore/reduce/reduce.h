// Chapter 5 of Hamann (1991): data reduction of a triangulated surface by
// iterative triangle removal. Each triangle is weighted by its angle weight
// and the absolute curvature at its vertices (5.21-5.23); the lightest
// removable triangle is replaced by one point fitted to its platelet
// (5.26-5.29, or the implicit quadric of 5.30-5.33), joined to the platelet's
// boundary polygon (5.40) and improved by diagonal swaps (Definition 5.15).
#pragma once

#include <string>
#include <vector>

#include "../mesh.h"
#include "../progress.h"

namespace isoform {

enum class ReducePoint {
  Quadratic = 0,  // bivariate quadratic least squares in the triangle's plane (5.26-5.29)
  Quadric = 1     // implicit quadric through the platelet, cut by the normal line (5.30-5.33)
};

struct ReduceOptions {
  double keep_fraction = 0.1;  // stop at this fraction of the input's triangles, (0, 1]
  double tolerance = 0.0;      // two-sided distance bound, world units; 0 = off (see docs/reduce.md)
  bool lock_boundary = false;  // never remove a triangle with an open corona (Remark 5.8)
  ReducePoint point = ReducePoint::Quadratic;
  // The mesh is the graph z = f(x, y) of a function: keep its (x, y) domain
  // covered (boundary points stay on straight boundary lines, new points on
  // the boundary keep their (x, y)), and allow the RMS stop of Remark 5.10.
  bool graph = false;
  double graph_rms_tolerance = 0.0;  // stop before the RMS height error (5.41) exceeds it; 0 = off
  bool swaps = true;                 // Lawson-like swaps after the fan (Definition 5.15)
  bool measure_error = false;        // report max_distance without a tolerance (measured on the result)
  // Beyond the seed: move the new point along its normal (graph: vertically)
  // to the least-squares best place for the original vertices under the new
  // triangles (Tracker::refine). Off reproduces the seed's point.
  bool refine_point = true;
  // Beyond the seed: when the fitted point fails the half-plane test or a
  // guard on a closed corona, try T's vertices in its place, then a point
  // above the polygon's kernel (kernel.h).
  bool vertex_fallback = true;
  // Beyond the seed: reduce only the parts that pass every entry check and
  // copy the others unchanged, instead of refusing the mesh (manifold_parts.h).
  bool manifold_parts_only = false;
  // A refusal that depends on the triangle's own neighbourhood alone is not
  // computed again in the next pass while that neighbourhood is unchanged
  // (speculate.h). Only time depends on it: off gives the same result.
  bool remember_refusals = true;
  // Removals computed ahead of their turn, in batches on the crew's threads
  // (speculate.h); off computes each at its turn against the mesh as it is.
  // Only time depends on it: off gives the same result (the tests compare).
  bool compute_ahead = true;
  // Beyond the seed: refuse a removal whose new triangles would cross a
  // triangle of the mesh outside its platelet (face_grid.h), so the result
  // does not overlap itself where two sheets of the input lie close. Off by
  // default: its queries cost time on every removal (docs/reduce.md,
  // "Beyond the seed").
  bool prevent_overlap = false;
};

// Why a candidate triangle was not removed when its turn came.
struct ReduceRefusals {
  long long corona = 0;      // corona discontinuous, cyclic, or too small (Def. 5.3, 5.4)
  long long half_plane = 0;  // the inserted point fails Theorem 5.3
  long long flip = 0;        // a new triangle would turn over or be degenerate
  long long nonmanifold = 0; // a new edge would be shared by three triangles, or a duplicate
  long long boundary = 0;    // locked boundary, or the boundary would leave its line (graph)
  long long tolerance = 0;   // the distance tolerance would be exceeded
  long long overlap = 0;     // a new triangle would cross another one (prevent_overlap)
};

struct ReduceStats {
  long long triangles_before = 0, triangles_after = 0;
  long long vertices_before = 0, vertices_after = 0;
  long long removals = 0;    // triangles replaced by a point
  long long swaps = 0;       // diagonal swaps made
  long long vertex_points = 0;  // removals whose point is a vertex of T (vertex_fallback)
  long long kernel_points = 0;  // removals whose point lies above the polygon's kernel (the same)
  int passes = 0;            // passes of Remark 5.9
  long long refusals_remembered = 0;  // refused tries not computed again (remember_refusals)
  bool curvature_computed = false;  // the input had none, so Chapter 4 ran first
  double max_distance = 0.0; // distance bound at vertices, both ways (tolerance or measure_error), world units
  double graph_rms = 0.0;    // RMS height error at the original vertices (graph mode)
  int stop_reason = 0;       // 0 target reached, 1 nothing removable, 2 tolerance, 3 RMS tolerance
  ReduceRefusals refused;
  // manifold_parts_only: the parts copied unchanged, their triangles, and
  // why, one line each ("part of N triangles from triangle T: <problem>").
  long long parts_left_alone = 0, triangles_left_alone = 0;
  std::vector<std::string> left_alone;
};

// Reduces mesh in place. The mesh must be a manifold, consistently oriented
// triangulation with finite coordinates that does not overlap itself (else
// InvalidArgument naming the first offending edge, vertex or triangles;
// validate.h), unless manifold_parts_only. Curvature is computed first
// (Chapter 4, default method) when the mesh has none. The Euler
// characteristic, the parts and the genus are kept. On return mesh holds the
// reduced points, normals, triangles, neighbours, parts and per-vertex
// curvature (surviving vertices keep theirs; new points carry Theorem 5.5's
// or 5.6's); colours and loose edges are dropped. Throws Cancelled when
// progress asks, with the mesh unchanged.
ReduceStats reduce_mesh(Mesh& mesh, const ReduceOptions& options, const Progress& progress);

}  // namespace isoform
