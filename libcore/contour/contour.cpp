// The contour driver: bricks in parallel, merge, orientation, topology.
#include "contour.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cmath>

#include "../errors.h"
#include "merge.h"

namespace isoform {
namespace {

bool wants_increasing(const ScalarGrid& grid, Orientation o) {
  if (o == Orientation::Auto) return grid.grid_class == GridClass::LevelSet;
  return o == Orientation::Increasing;
}

void contour_bricks(const ScalarGrid& grid, double iso, ContourMethod method, const Progress& progress,
                    BrickTables& tables) {
  const BrickSource& source = *grid.bricks;
  const size_t n = source.brick_count();
  std::vector<BrickMesh> all(n);
  struct Scratch {
    Brick brick;
    BrickContourer contourer;
  };
  tbb::enumerable_thread_specific<Scratch> scratch(
      [&] { return Scratch{Brick(), BrickContourer(grid.index_to_world, iso, method)}; });
  std::atomic<size_t> done{0};
  std::atomic<bool> stop{false};
  // NOTE: a small grain: a 16^3 brick is work enough for a task, and a
  // small grid (headsq: about 100 bricks) must still split evenly.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 2), [&](const tbb::blocked_range<size_t>& r) {
    if (stop.load(std::memory_order_relaxed)) return;
    Scratch& s = scratch.local();
    BrickStores& store = tables.stores.local();
    for (size_t b = r.begin(); b != r.end(); ++b) {
      if (!source.may_cross(b, iso)) continue;
      source.fill(b, s.brick);
      s.contourer.run(s.brick, all[b], store);
    }
    const size_t d = done.fetch_add(r.size()) + r.size();
    progress.fraction(float(d) / float(n));
    if (progress.cancelled()) stop = true;
  });
  if (stop) throw Cancelled("contour cancelled");
  size_t crossing = 0;
  for (const BrickMesh& bm : all) crossing += bm.vertex_count > 0;
  tables.bricks.reserve(crossing);
  for (const BrickMesh& bm : all)
    if (bm.vertex_count > 0) tables.bricks.push_back(bm);
}

// In index space each triangle winds counter-clockwise around the
// gradient (the cell method winds each polygon around increasing f, and so
// does the tetra table); a mirroring transform (negative determinant)
// reverses that in world space.
MergeOrientation orientation(bool increasing, double determinant) {
  MergeOrientation o;
  o.reverse = increasing == (determinant < 0);
  o.negate = !increasing;
  return o;
}

// Vertices whose Zucker-Hummel estimate vanished (a flat 3x3x3 region) take
// the area-weighted mean of their triangles' normals.
void repair_normals(Mesh& mesh) {
  std::vector<uint8_t> missing(mesh.vertex_count());
  bool any = false;
  for (size_t v = 0; v < missing.size(); ++v) {
    const float* n = &mesh.normals[3 * v];
    missing[v] = n[0] == 0 && n[1] == 0 && n[2] == 0;
    any |= missing[v];
  }
  if (!any) return;
  std::vector<double> acc(mesh.normals.size(), 0.0);
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const int32_t* tri = &mesh.triangles[3 * t];
    const float* p = &mesh.points[3 * size_t(tri[0])];
    const float* q = &mesh.points[3 * size_t(tri[1])];
    const float* r = &mesh.points[3 * size_t(tri[2])];
    const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    const double w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    for (int m = 0; m < 3; ++m)
      if (missing[size_t(tri[m])])
        for (int a = 0; a < 3; ++a) acc[3 * size_t(tri[m]) + a] += c[a];
  }
  for (size_t v = 0; v < missing.size(); ++v) {
    if (!missing[v]) continue;
    const double len = std::sqrt(acc[3 * v] * acc[3 * v] + acc[3 * v + 1] * acc[3 * v + 1] +
                                 acc[3 * v + 2] * acc[3 * v + 2]);
    for (int a = 0; a < 3; ++a) mesh.normals[3 * v + a] = len > 0 ? float(acc[3 * v + a] / len) : 0.0f;
  }
}

Mesh contour_in_arena(const ScalarGrid& grid, const ContourOptions& options, const Progress& progress) {
  Mesh mesh;
  const double iso = resolve_isovalue(grid, options);
  mesh.contour.isovalue = iso;
  mesh.contour.isovalue_was_auto = options.auto_isovalue;
  progress.stage(ISOFORM_STAGE_CONTOUR);
  BrickTables tables;
  contour_bricks(grid, iso, options.method, progress, tables);
  progress.stage(ISOFORM_STAGE_MERGE);
  const bool increasing = wants_increasing(grid, options.orientation);
  const bool missing =
      merge_bricks(tables, orientation(increasing, grid.index_to_world.determinant()), mesh, progress);
  if (missing) repair_normals(mesh);
  progress.stage(ISOFORM_STAGE_DONE);
  return mesh;
}

}  // namespace

double resolve_isovalue(const ScalarGrid& grid, const ContourOptions& options) {
  if (!options.auto_isovalue) {
    if (!std::isfinite(options.isovalue)) throw InvalidArgument("the isovalue must be finite");
    return options.isovalue;
  }
  if (grid.grid_class == GridClass::LevelSet) return 0.0;
  return 0.5 * (grid.value_min + grid.value_max);
}

Mesh contour(const ScalarGrid& grid, const ContourOptions& options, const Progress& progress) {
  if (!grid.bricks) throw InvalidArgument("grid '" + grid.name + "' has no data");
  if (options.threads < 0) throw InvalidArgument("threads must be 0 (all cores) or positive");
  if (options.threads == 0) return contour_in_arena(grid, options, progress);
  tbb::task_arena arena(options.threads);
  Mesh mesh;
  arena.execute([&] { mesh = contour_in_arena(grid, options, progress); });
  return mesh;
}

}  // namespace isoform
