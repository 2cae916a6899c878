// Metro-style two-sided distance between two triangle meshes (Cignoni,
// Rocchini and Scopigno's method, written for isoform's reduction
// benchmark): points sampled uniformly by area on one surface, each point's
// distance to the nearest point of the other, both ways. The maximum of
// either side estimates the Hausdorff distance from below; RMS is
// area-weighted because the samples are.
#pragma once

#include <cstdint>
#include <vector>

#include "closest_point.h"

namespace isoform_reduce_bench {

// Points on a surface: `area_samples` drawn uniformly by area (the RMS is
// taken over these), then every vertex that a triangle uses (they count for
// the maximum only: a surface's farthest points are often its corners).
struct SurfaceSamples {
  std::vector<double> points;  // 3 per sample, the area samples first
  size_t area_samples = 0;
  double area = 0;             // total area of the surface
  size_t count() const { return points.size() / 3; }
};

// count area samples from a fixed seed (the same mesh and seed give the same
// points). Triangles of zero area get none.
SurfaceSamples sample_surface(const MeshView& mesh, size_t count, uint64_t seed);

struct SidedError {
  double max = 0;   // over all samples
  double rms = 0;   // over the area samples
  double mean = 0;  // over the area samples
  size_t samples = 0;
};

// Distances from every sample to the tree's mesh (in parallel with TBB).
SidedError sided_error(const SurfaceSamples& from, const TriangleTree& to);

struct TwoSidedError {
  SidedError a_to_b, b_to_a;
  double max() const { return a_to_b.max > b_to_a.max ? a_to_b.max : b_to_a.max; }
  double rms() const { return a_to_b.rms > b_to_a.rms ? a_to_b.rms : b_to_a.rms; }
};

// Both sides from the given samples and trees (so a fixed original's are
// made once for many reduced meshes).
TwoSidedError two_sided_error(const SurfaceSamples& a_samples, const TriangleTree& a_tree,
                              const SurfaceSamples& b_samples, const TriangleTree& b_tree);

// Length of the diagonal of the bounding box of the vertices that triangles use.
double bbox_diagonal(const MeshView& mesh);

}  // namespace isoform_reduce_bench
