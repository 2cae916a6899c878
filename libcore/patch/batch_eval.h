// Batch evaluation of the side-vertex patch over one triangle: the surface
// of fast_eval.h (and patch_eval.h, the reference), organised for many
// samples at once.
// - Samples on one ray from vertex i (the same t = u_k / (u_j + u_k), exact
//   double equality) share building block i's radial conic, so each distinct
//   t's conic (the edge's point and normal at t, the plane, tangents, half
//   angles, weight, Bezier points, all as jets in t) is built once.
// - Conics and patch points are computed four at a time, one per lane of a
//   vector of doubles (lanes_jet.h), with AVX2 and FMA where the CPU has
//   them (picked at run time) and SSE2 otherwise.
// - Samples whose data take a rare branch (a degenerate radial chord,
//   opposite normals, no conic plane, a corner) are evaluated one by one by
//   SideVertexSurface::evaluate_order, so every sample gets what
//   evaluate_order gives, to rounding (tests/patch: Batch.*).
// - Which samples share a ray depends on the samples only: a BatchPlan
//   finds it once for a sample set (a lattice) used on many triangles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "../surface.h"
#include "side_vertex_surface.h"

namespace isoform::patch {

// Which lane code runs: the best the CPU has (AVX2 + FMA, else SSE2), or
// SSE2 always (for tests of that path on AVX2 machines).
enum class BatchIsa { Best, Baseline };

namespace detail {
constexpr size_t kBatchChunk = 64;
// Up to kBatchChunk samples: those for the lanes (not a corner, inside the
// triangle), and per building block i the distinct t and each lane
// sample's index into them.
struct BatchChunk {
  size_t start = 0, n = 0, m = 0;
  uint8_t sample[kBatchChunk];  // lane sample -> position in the chunk
  bool lane[kBatchChunk];       // position -> on the lane path
  double t[3][kBatchChunk];     // distinct t of block i, ascending
  size_t distinct[3];
  uint8_t index[3][kBatchChunk];  // lane sample -> its t in t[i]
};
}  // namespace detail

// The parameter side of a batch, made once for a sample set and used for
// every triangle (it depends on the (u, v) and the blend only): which
// samples are corners or outside the triangle, and which lie on one ray
// from a vertex.
class BatchPlan {
 public:
  BatchPlan(const PatchOptions& options, const double* u, const double* v, size_t n);
  size_t size() const { return u_.size(); }
  Blend blend() const { return blend_; }
  const double* u() const { return u_.data(); }
  const double* v() const { return v_.data(); }
  const std::vector<detail::BatchChunk>& chunks() const { return chunks_; }

 private:
  Blend blend_;
  std::vector<double> u_, v_;
  std::vector<detail::BatchChunk> chunks_;
};

// out[i] and ok[i] for the plan's sample i over triangle `tri`, as
// s.evaluate_order(tri, u[i], v[i], out[i], second) would give (to
// rounding). A plan made for another blend is remade for this call.
void evaluate_batch(const SideVertexSurface& s, size_t tri, const BatchPlan& plan, SurfaceSample* out, bool* ok,
                    bool second, BatchIsa isa = BatchIsa::Best);

// The same with a plan made for this call: any n, any order, duplicates
// allowed.
void evaluate_batch(const SideVertexSurface& s, size_t tri, const double* u, const double* v, size_t n,
                    SurfaceSample* out, bool* ok, bool second, BatchIsa isa = BatchIsa::Best);

}  // namespace isoform::patch
