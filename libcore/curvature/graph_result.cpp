// Result grids of the curvature of a trivariate graph.
#include "graph_result.h"

#include <algorithm>
#include <cmath>

#include "../errors.h"

namespace isoform {

const char* const kGraphGridNames[kGraphGrids] = {"mean", "gauss", "k1", "k2", "k3"};

namespace {

// One result grid as bricks: own samples from the brick, the halo from the
// bricks around it on the lattice.
class ResultBricks : public BrickSource {
 public:
  ResultBricks(std::shared_ptr<const std::vector<GraphResultBrick>> bricks,
               std::shared_ptr<const BrickLattice> lattice, int grid)
      : bricks_(std::move(bricks)), lattice_(std::move(lattice)), grid_(grid) {}
  size_t brick_count() const override { return bricks_->size(); }
  void fill(size_t index, Brick& out) const override {
    const GraphResultBrick& r = (*bricks_)[index];
    out.resize(r.origin, r.cells, true);
    std::fill(out.samples.begin(), out.samples.end(), 0.0f);
    std::fill(out.defined.begin(), out.defined.end(), uint8_t(0));
    const Index3 d = out.dims();
    for (int k = -1; k < d[2] - 1; ++k)
      for (int j = -1; j < d[1] - 1; ++j)
        for (int i = -1; i < d[0] - 1; ++i) {
          const bool own = i >= 0 && j >= 0 && k >= 0 && i < r.cells[0] && j < r.cells[1] && k < r.cells[2];
          const Index3 p{r.origin[0] + i, r.origin[1] + j, r.origin[2] + k};
          const size_t b = own ? index : lattice_->find(p);
          if (b == BrickLattice::npos) continue;
          const GraphResultBrick& src = (*bricks_)[b];
          const size_t at = (size_t(p[2] - src.origin[2]) * size_t(src.cells[1]) + size_t(p[1] - src.origin[1])) *
                                size_t(src.cells[0]) +
                            size_t(p[0] - src.origin[0]);
          if (!src.mask[at]) continue;
          out.samples[out.at(i, j, k)] = src.values[size_t(grid_)][at];
          out.defined[out.at(i, j, k)] = 1;
        }
  }

 private:
  std::shared_ptr<const std::vector<GraphResultBrick>> bricks_;
  std::shared_ptr<const BrickLattice> lattice_;
  int grid_;
};

double nearest_rank(const std::vector<float>& sorted, double percent) {
  return sorted[size_t(std::llround(percent / 100.0 * double(sorted.size() - 1)))];
}

GridFacts facts_of(const std::vector<GraphResultBrick>& bricks, int grid, const Affine& map) {
  GridFacts f;
  f.name = kGraphGridNames[grid];
  f.value_type = "float";
  f.grid_class = GridClass::Other;
  f.is_scalar = true;
  f.index_to_world = map;
  bool first = true;
  for (const GraphResultBrick& b : bricks) {
    size_t at = 0;
    for (int k = 0; k < b.cells[2]; ++k)
      for (int j = 0; j < b.cells[1]; ++j)
        for (int i = 0; i < b.cells[0]; ++i, ++at) {
          if (!b.mask[at]) continue;
          const double v = b.values[size_t(grid)][at];
          const Index3 p{b.origin[0] + i, b.origin[1] + j, b.origin[2] + k};
          if (first) {
            f.value_min = f.value_max = v;
            f.bbox_min = f.bbox_max = p;
            first = false;
          }
          f.value_min = std::min(f.value_min, v);
          f.value_max = std::max(f.value_max, v);
          for (int a = 0; a < 3; ++a) {
            f.bbox_min[a] = std::min(f.bbox_min[a], p[a]);
            f.bbox_max[a] = std::max(f.bbox_max[a], p[a]);
          }
          ++f.active_voxels;
        }
  }
  return f;
}

}  // namespace

GraphCurvatureVolume::GraphCurvatureVolume(std::string source_path, const Affine& index_to_world,
                                           std::vector<GraphResultBrick> bricks, const GraphCurvatureStats& stats)
    : source_path_(std::move(source_path)), stats_(stats) {
  std::vector<std::pair<Index3, Index3>> layout;
  for (const GraphResultBrick& b : bricks) layout.emplace_back(b.origin, b.cells);
  lattice_ = std::make_shared<BrickLattice>(layout);
  bricks_ = std::make_shared<const std::vector<GraphResultBrick>>(std::move(bricks));
  for (int g = 0; g < kGraphGrids; ++g) {
    facts_[size_t(g)] = facts_of(*bricks_, g, index_to_world);
    auto grid = std::make_shared<ScalarGrid>();
    grid->name = kGraphGridNames[g];
    grid->grid_class = GridClass::Other;
    grid->index_to_world = index_to_world;
    grid->background = 0.0;
    grid->value_min = facts_[size_t(g)].value_min;
    grid->value_max = facts_[size_t(g)].value_max;
    grid->bricks = std::make_shared<ResultBricks>(bricks_, lattice_, g);
    grid->defined_is_active = true;
    grids_[size_t(g)] = std::move(grid);
  }
}

GridFacts GraphCurvatureVolume::facts(int i) const {
  if (i < 0 || i >= kGraphGrids) throw InvalidArgument("curvature result: grid index out of range");
  return facts_[size_t(i)];
}

std::shared_ptr<const ScalarGrid> GraphCurvatureVolume::load(int i) const {
  if (i < 0 || i >= kGraphGrids) throw InvalidArgument("curvature result: grid index out of range");
  return grids_[size_t(i)];
}

void summarise_graph_results(const std::vector<GraphResultBrick>& bricks, GraphCurvatureStats& stats) {
  for (int g = 0; g < kGraphGrids; ++g) {
    std::vector<float> v;
    double sum = 0;
    for (const GraphResultBrick& b : bricks)
      for (size_t at = 0; at < b.mask.size(); ++at)
        if (b.mask[at]) {
          v.push_back(b.values[size_t(g)][at]);
          sum += v.back();
        }
    GraphSummary& s = stats.summary[size_t(g)];
    s = GraphSummary{};
    if (v.empty()) continue;
    std::sort(v.begin(), v.end());
    s.min = v.front();
    s.max = v.back();
    s.mean = sum / double(v.size());
    s.p01 = nearest_rank(v, 1);
    s.p05 = nearest_rank(v, 5);
    s.p25 = nearest_rank(v, 25);
    s.p50 = nearest_rank(v, 50);
    s.p75 = nearest_rank(v, 75);
    s.p95 = nearest_rank(v, 95);
    s.p99 = nearest_rank(v, 99);
  }
}

}  // namespace isoform
