// The tangent-plane-continuous side-vertex surface of Hamann (1991),
// Chapter 6: over each triangle of a mesh with vertex normals, three building
// blocks made by radial projection from each vertex to a conic on the opposite
// edge (Section 6.3), blended with the weights of Theorem 6.1. It passes
// through every vertex with the given normal there, and neighbouring patches
// share their boundary curves and the normals along them (tangent-plane
// continuity). Parameters follow surface.h: (u, v) with weight 1-u-v on the
// triangle's first vertex.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "../mesh.h"
#include "../surface.h"
#include "edge_curve.h"
#include "edge_poly.h"

namespace isoform::patch {

// The blend (6.1): w_i proportional to u_j u_k as printed in (6.2)-(6.3), or
// to (u_j u_k)^2, which also has Theorem 6.1 (iii) (zero derivative of w_i
// across edge e_i). The printed weights do not: their derivative across e_i
// does not vanish. Theorem 6.2's proof does not need (iii), so both give
// tangent-plane continuity, but with the printed ones the surface can turn
// sharply in a thin layer along the edges.
enum class Blend { Printed = 0, Squared = 1 };

// A user weight for the conic of one mesh edge (either vertex order).
struct EdgeTension {
  int32_t a = 0, b = 0;
  double omega = 1.0;  // > 0
};

struct PatchOptions {
  // NOTE: the default is the one measured better (docs/patch.md, "Which blend").
  Blend blend = Blend::Squared;
  // omega of every conic: 0 (default) = automatic, sin(gamma/2) (Theorem 6.3);
  // W > 0: omega = W a / sqrt(W^2 + a^2) with a = sin(gamma/2), i.e. about
  // W where W is well below a, never above a, so curves stay finite for
  // parallel tangents. Lower weights pull the surface toward the triangles.
  double tension = 0.0;
  // Per-edge weights for the boundary conics (override tension there). The
  // radial curves from a vertex take 1/omega interpolated between its two
  // edges, so they still meet the boundary curves (Definition 6.2 (iv)).
  std::vector<EdgeTension> edge_tension;
  // Fill SurfaceSample's second derivatives (exact, forward-mode jets); off
  // saves the second-order terms of every jet, a large part of the
  // evaluation's work.
  bool second_derivatives = true;
};

// What the construction met.
struct PatchStats {
  long long edges = 0;
  long long nonconvex_edges = 0;        // edge conics with an inflection
  long long opposite_normal_edges = 0;  // n0 = -n3 on an edge
  long long fallback_plane_edges = 0;   // no conic plane from the data
  // Triangles whose face normal points against the sum of their vertex
  // normals: their patches are oriented against the data, and meet their
  // neighbours folded over (orientation.h finds the folded edges).
  long long inverted_triangles = 0;
};

// One mesh edge in a triangle: its curve, and whether the triangle's local
// order (from vertex i+1 to i+2) runs against the curve's.
struct TriangleEdge {
  int32_t edge = 0;
  bool reversed = false;
};

class SideVertexSurface final : public TriangleSurface {
 public:
  // Throws InvalidArgument when the mesh cannot carry the surface.
  SideVertexSurface(const Mesh& mesh, const PatchOptions& options);

  size_t triangle_count() const override { return triangles_.size() / 3; }
  // Point, exact normal and derivatives; false (sample unspecified) where
  // u, v lie outside the triangle or the data make the surface undefined.
  bool evaluate(size_t triangle, double u, double v, SurfaceSample& out) const override;
  // As evaluate, with second derivatives only when `second` (whatever the
  // options say). The fast path (fast_eval.h).
  bool evaluate_order(size_t triangle, double u, double v, SurfaceSample& out, bool second) const;
  // The same surface by the reference path (patch_eval.h: the whole
  // construction in two-variable jets); for tests of the fast path.
  bool evaluate_reference(size_t triangle, double u, double v, SurfaceSample& out, bool second) const;
  // The point only (the fast path of tessellation); false as above.
  bool point(size_t triangle, double u, double v, V3d& out) const;

  // The shared curve of mesh edge e and its end vertices (lower first).
  const EdgeCurve& edge_curve(size_t e) const { return curves_[e]; }
  const EdgePoly& edge_poly(size_t e) const { return polys_[e]; }
  // d/dt of edge e's curve at its end `end` (0: t = 0, 1: t = 1), for the
  // corner rule.
  const V3d& edge_end_derivative(size_t e, int end) const { return end_derivatives_[2 * e + size_t(end)]; }
  size_t edge_count() const { return curves_.size(); }
  int32_t edge_vertex(size_t e, int end) const { return edge_vertices_[2 * e + end]; }
  // Edge slot i of triangle t is the edge opposite its vertex i.
  TriangleEdge triangle_edge(size_t t, int i) const { return triangle_edges_[3 * t + i]; }
  int32_t triangle_vertex(size_t t, int i) const { return triangles_[3 * t + i]; }
  const V3d& vertex(size_t i) const { return points_[i]; }
  const V3d& vertex_normal(size_t i) const { return normals_[i]; }
  size_t vertex_count() const { return points_.size(); }
  const PatchStats& stats() const { return stats_; }
  const PatchOptions& options() const { return options_; }

  // For the evaluation templates (patch_eval.h).
  double edge_inv_tension(size_t e) const { return edge_inv_tension_[e]; }
  double inv_tension() const { return inv_tension_; }

 private:
  void build_edges(const std::vector<EdgeTension>& tension);
  bool corner(size_t triangle, int i, SurfaceSample& out) const;
  template <class Eval>
  bool evaluate_with(size_t triangle, double u, double v, SurfaceSample& out, bool second, Eval eval) const;

  PatchOptions options_;
  std::vector<V3d> points_, normals_;
  std::vector<int32_t> triangles_;
  std::vector<int32_t> edge_vertices_;
  std::vector<TriangleEdge> triangle_edges_;
  std::vector<EdgeCurve> curves_;
  std::vector<EdgePoly> polys_;
  std::vector<V3d> end_derivatives_;
  std::vector<double> edge_inv_tension_;
  double inv_tension_ = 0.0;
  PatchStats stats_;
};

// nullptr and a message in `error` when the mesh cannot carry the surface:
// no normals, a zero or non-finite normal or point, a triangle with a
// repeated or coincident vertex, bad options.
std::unique_ptr<TriangleSurface> make_side_vertex_surface(const Mesh& mesh, const PatchOptions& options,
                                                          std::string& error);

}  // namespace isoform::patch
