// The curvature of the graph of f (Hamann 1991, Section 4.3) at every
// active sample of a grid, brick by brick and in parallel.
#pragma once

#include <memory>
#include <string>

#include "../progress.h"
#include "../volume.h"
#include "graph_result.h"

namespace isoform {

struct GraphVolumeOptions {
  GraphMethod method = GraphMethod::Default;
  int threads = 0;  // 0 = all cores, 1 = serial
};

// Reads grid.active_bricks when set (a sparse file's active set), else
// grid.bricks, and computes results at each brick's own defined samples
// from defined samples only, reading up to kGraphReach samples into the
// neighbouring bricks of the lattice (graph_lattice.h), so brick seams do
// not show. World coordinates throughout (the grid's transform). The same
// input gives the same bits for any thread count: each point's arithmetic
// does not depend on the schedule, and sums run in brick order. Throws
// Cancelled when progress asks, InvalidArgument for a singular transform.
std::shared_ptr<GraphCurvatureVolume> graph_curvature_volume(const ScalarGrid& grid, const std::string& source_path,
                                                             const GraphVolumeOptions& options,
                                                             const Progress& progress);

}  // namespace isoform
