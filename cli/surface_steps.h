// The smooth-surface steps that `pipeline` runs after the reduction: the
// side-vertex surface (Chapter 6) tessellated at a level, and the comparison
// with the Loop limit surface written as a study folder.
#pragma once

#include <string>

#include "cli.h"
#include "progress.h"
#include "report.h"

namespace isoform::cli {

// The side-vertex surface over mesh (its normals) tessellated into 4^level
// triangles per triangle. Failures name `input`.
MeshPtr smooth_surface(const isoform_mesh* mesh, int level, const std::string& input,
                       const ProgressOptions& progress);

// Measures the flat triangles, the Loop limit surface and the side-vertex
// surface of mesh at lattice level `level`, against grid `grid` of volume at
// `isovalue` (deviation in voxels); writes report.json, samples.csv,
// report.md and surface-<name>.ply into folder (created). Returns the
// per-surface summary.
Json compare_study(const isoform_mesh* mesh, const isoform_volume* volume, int grid, double isovalue,
                   int level, const std::string& input, const std::string& folder,
                   const ProgressOptions& progress);

}  // namespace isoform::cli
