// Chapter 3 of Hamann (1991) as one call: a scalar grid to the seed's tables
// V, T, N, neighbours and parts.
#pragma once

#include "../mesh.h"
#include "../progress.h"
#include "../volume.h"
#include "brick_contour.h"

namespace isoform {

enum class Orientation { Auto = 0, Increasing = 1, Decreasing = 2 };

struct ContourOptions {
  double isovalue = 0.0;     // grid value units
  bool auto_isovalue = true; // level set: 0; other grids: midpoint of the value range
  ContourMethod method = ContourMethod::Cells;
  Orientation orientation = Orientation::Auto;  // Auto: level set increasing, else decreasing
  int threads = 0;           // 0: all cores; 1: serial
};

// Contours the grid. Bricks are contoured in parallel, then merged (merge.h),
// oriented, and given neighbours and parts (topology.h). Vertices whose
// gradient estimate vanishes take the mean normal of their triangles.
// Throws Cancelled when progress asks to stop.
Mesh contour(const ScalarGrid& grid, const ContourOptions& options, const Progress& progress);

// The isovalue contour() uses for these options.
double resolve_isovalue(const ScalarGrid& grid, const ContourOptions& options);

}  // namespace isoform
