// The result of the curvature of a trivariate graph over a volume: five
// float grids `mean`, `gauss`, `k1`, `k2`, `k3` with the input grid's
// transform, defined exactly at the input's active (defined) samples, as a
// VolumeFile that vdbio writes and the C API wraps as an isoform_volume.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "../volume.h"
#include "graph_lattice.h"
#include "graph_point.h"

namespace isoform {

constexpr int kGraphGrids = 5;
// Grid names in order: H, K, k1 >= k2 >= k3.
extern const char* const kGraphGridNames[kGraphGrids];

// Results of one input brick at its own samples, x fastest.
struct GraphResultBrick {
  Index3 origin{0, 0, 0}, cells{0, 0, 0};
  std::vector<uint8_t> mask;                       // 1 where the input was defined
  std::array<std::vector<float>, kGraphGrids> values;  // 0 where mask is 0
};

// Distribution of one result grid over its defined samples (nearest-rank
// percentiles).
struct GraphSummary {
  double min = 0, max = 0, mean = 0;
  double p01 = 0, p05 = 0, p25 = 0, p50 = 0, p75 = 0, p95 = 0, p99 = 0;
};

struct GraphCurvatureStats {
  GraphMethod method = GraphMethod::Default;
  long long points = 0;
  std::array<long long, kGraphFitCount> fits{};  // points per GraphFit
  std::array<GraphSummary, kGraphGrids> summary;
};

class GraphCurvatureVolume : public VolumeFile {
 public:
  // source_path is the input's path: writers then refuse to overwrite it.
  GraphCurvatureVolume(std::string source_path, const Affine& index_to_world, std::vector<GraphResultBrick> bricks,
                       const GraphCurvatureStats& stats);

  std::string path() const override { return source_path_; }
  int grid_count() const override { return kGraphGrids; }
  GridFacts facts(int i) const override;
  // Bricks with the defined flags of the input's active samples (halo
  // included, from neighbouring bricks), background 0, class Other, and
  // defined_is_active set so that zero curvature stays active when written.
  std::shared_ptr<const ScalarGrid> load(int i) const override;
  const GraphCurvatureStats& stats() const { return stats_; }

 private:
  std::string source_path_;
  std::shared_ptr<const std::vector<GraphResultBrick>> bricks_;
  std::shared_ptr<const BrickLattice> lattice_;
  std::array<std::shared_ptr<ScalarGrid>, kGraphGrids> grids_;
  std::array<GridFacts, kGraphGrids> facts_;
  GraphCurvatureStats stats_;
};

// Fills stats.summary from the results (deterministic: sorts a copy).
void summarise_graph_results(const std::vector<GraphResultBrick>& bricks, GraphCurvatureStats& stats);

}  // namespace isoform
