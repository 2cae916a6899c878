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
#pragma once

#include <cstddef>

#include "../surface.h"

namespace isoform::patch {

class SideVertexSurface;

// Which lane code runs: the best the CPU has (AVX2 + FMA, else SSE2), or
// SSE2 always (for tests of that path on AVX2 machines).
enum class BatchIsa { Best, Baseline };

// out[i] and ok[i] for (u[i], v[i]) over triangle `tri`, as
// s.evaluate_order(tri, u[i], v[i], out[i], second) would give (to
// rounding); any n, any order, duplicates allowed.
void evaluate_batch(const SideVertexSurface& s, size_t tri, const double* u, const double* v, size_t n,
                    SurfaceSample* out, bool* ok, bool second, BatchIsa isa = BatchIsa::Best);

}  // namespace isoform::patch
