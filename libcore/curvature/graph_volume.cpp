// Curvature of a trivariate graph over a volume's bricks (Section 4.3).
#include "graph_volume.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>

#include "../errors.h"
#include "graph_block.h"

namespace isoform {
namespace {

struct BrickWork {
  GraphResultBrick result;
  std::array<long long, kGraphFitCount> fits{};
};

// Origin and cells of every brick, which the lattice needs before any
// brick's neighbours can be found.
std::vector<std::pair<Index3, Index3>> brick_layout(const BrickSource& source) {
  std::vector<std::pair<Index3, Index3>> layout(source.brick_count());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, layout.size()), [&](const tbb::blocked_range<size_t>& r) {
    Brick brick;
    for (size_t b = r.begin(); b != r.end(); ++b) {
      source.fill(b, brick);
      layout[b] = {brick.origin, brick.cells};
    }
  });
  return layout;
}

// The brick's samples and, within kGraphReach, its lattice neighbours' own.
void gather(const BrickSource& source, const BrickLattice& lattice, size_t b, Brick& brick, Brick& scratch,
            GraphBlock& block) {
  source.fill(b, brick);
  block.reset(brick.origin, brick.cells);
  block.add_brick(brick);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0 && dz == 0) continue;
        const size_t n = lattice.neighbour(b, {dx, dy, dz});
        if (n == BrickLattice::npos) continue;
        source.fill(n, scratch);
        block.add_brick_own(scratch);
      }
}

void compute_brick(const GraphBlock& block, const GraphAxes& axes, GraphMethod method, BrickWork& work) {
  GraphResultBrick& r = work.result;
  r.origin = block.first();
  r.cells = block.count();
  const size_t n = size_t(r.cells[0]) * size_t(r.cells[1]) * size_t(r.cells[2]);
  r.mask.assign(n, 0);
  for (auto& v : r.values) v.assign(n, 0.0f);
  size_t at = 0;
  for (int k = 0; k < r.cells[2]; ++k)
    for (int j = 0; j < r.cells[1]; ++j)
      for (int i = 0; i < r.cells[0]; ++i, ++at) {
        const Index3 p{r.origin[0] + i, r.origin[1] + j, r.origin[2] + k};
        if (!block.is_defined(p)) continue;
        const GraphCurvature c = graph_curvature_at(block.samples(p), axes, method);
        const GraphPrincipal& q = c.curvature;
        const double v[kGraphGrids] = {q.mean, q.gauss, q.k1, q.k2, q.k3};
        r.mask[at] = 1;
        for (int g = 0; g < kGraphGrids; ++g) r.values[size_t(g)][at] = float(v[g]);
        ++work.fits[size_t(c.fit)];
      }
}

}  // namespace

std::shared_ptr<GraphCurvatureVolume> graph_curvature_volume(const ScalarGrid& grid, const std::string& source_path,
                                                             const GraphVolumeOptions& options,
                                                             const Progress& progress) {
  if (options.threads < 0) throw InvalidArgument("curvature: threads must be 0 (all cores) or more");
  const GraphAxes axes = GraphAxes::of(grid.index_to_world);
  const BrickSource& source = grid.active_bricks ? *grid.active_bricks : *grid.bricks;
  std::vector<BrickWork> work(source.brick_count());
  std::atomic<size_t> done{0};
  std::atomic<bool> cancelled{false};
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    const BrickLattice lattice(brick_layout(source));
    tbb::parallel_for(tbb::blocked_range<size_t>(0, work.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
      Brick brick, scratch;
      GraphBlock block;
      for (size_t b = r.begin(); b != r.end(); ++b) {
        if (cancelled.load(std::memory_order_relaxed) || progress.cancelled()) {
          cancelled = true;
          return;
        }
        gather(source, lattice, b, brick, scratch, block);
        compute_brick(block, axes, options.method, work[b]);
        progress.fraction(float(double(++done) / double(work.size())));
      }
    });
  });
  if (cancelled) throw Cancelled("curvature cancelled");
  // Bricks in their source order; those without a defined sample add nothing.
  GraphCurvatureStats stats;
  stats.method = options.method;
  std::vector<GraphResultBrick> results;
  for (BrickWork& w : work) {
    long long points = 0;
    for (int f = 0; f < kGraphFitCount; ++f) {
      stats.fits[size_t(f)] += w.fits[size_t(f)];
      points += w.fits[size_t(f)];
    }
    stats.points += points;
    if (points > 0) results.push_back(std::move(w.result));
  }
  summarise_graph_results(results, stats);
  return std::make_shared<GraphCurvatureVolume>(source_path, grid.index_to_world, std::move(results), stats);
}

}  // namespace isoform
