// What each result is measured by: the two-sided sampled distance to the
// original (metro.h), for a graph also the vertical distance to its
// function at the same samples and at the original knots (Table 5.1's
// measure), and isoform's mesh statistics of the result
// (boundary and non-manifold edges, Euler characteristic, parts).
#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "reduce_bench.h"

namespace isoform_reduce_bench {
namespace {

void vertical_error(const Input& in, const SurfaceSamples& s, Measured& m) {
  double max = 0, sum2 = 0;
  for (size_t k = 0; k < s.count(); ++k) {
    const double* p = &s.points[3 * k];
    const double d = std::abs(p[2] - in.height(p[0], p[1]));
    max = std::max(max, d);
    if (k < s.area_samples) sum2 += d * d;
  }
  m.vertical_max = max;
  m.vertical_rms = s.area_samples ? std::sqrt(sum2 / double(s.area_samples)) : 0;
}

// The result's (x, y) projection locates each original knot: the triangle
// nearest to it in the plane (at distance 0 when it covers the knot), whose
// linear interpolant gives the height there.
void knot_error(const Input& in, const Surface& result, Measured& m) {
  Surface flat = result;
  for (size_t v = 0; v < flat.vertex_count(); ++v) flat.points[3 * v + 2] = 0;
  // The graph's triangles are counter-clockwise seen from above: one that is
  // not has turned over in the projection (so some knots lie under two
  // triangles and others under none).
  for (size_t t = 0; t < flat.triangle_count(); ++t) {
    const double* a = &flat.points[3 * size_t(flat.triangles[3 * t])];
    const double* b = &flat.points[3 * size_t(flat.triangles[3 * t + 1])];
    const double* c = &flat.points[3 * size_t(flat.triangles[3 * t + 2])];
    m.folded += (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]) <= 0;
  }
  const TriangleTree tree(flat.view());
  const double covered2 = 1e-24 * in.diagonal * in.diagonal;
  struct Sums {
    double max = 0, sum2 = 0;
    size_t uncovered = 0;
  };
  const size_t n = in.mesh.vertex_count();
  const Sums sums = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, n, 1024), Sums{},
      [&](const tbb::blocked_range<size_t>& r, Sums acc) {
        for (size_t k = r.begin(); k != r.end(); ++k) {
          const double x = in.mesh.points[3 * k], y = in.mesh.points[3 * k + 1];
          int32_t t = -1;
          if (tree.distance2({x, y, 0}, &t) > covered2 || t < 0) {
            ++acc.uncovered;
            continue;
          }
          const double* a = &result.points[3 * size_t(result.triangles[3 * size_t(t)])];
          const double* b = &result.points[3 * size_t(result.triangles[3 * size_t(t) + 1])];
          const double* c = &result.points[3 * size_t(result.triangles[3 * size_t(t) + 2])];
          const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
          if (det == 0) {
            ++acc.uncovered;
            continue;
          }
          // The knot lies in the triangle, so its barycentric coordinates are
          // in [0, 1]; on slivers rounding can throw them far out: clamp.
          double u = std::max(0.0, ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / det);
          double v = std::max(0.0, ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / det);
          if (u + v > 1) u /= u + v, v = 1 - u;
          const double d = std::abs(a[2] + u * (b[2] - a[2]) + v * (c[2] - a[2]) - in.height(x, y));
          acc.max = std::max(acc.max, d);
          acc.sum2 += d * d;
        }
        return acc;
      },
      [](Sums a, const Sums& b) {
        a.max = std::max(a.max, b.max);
        a.sum2 += b.sum2;
        a.uncovered += b.uncovered;
        return a;
      });
  m.knot_max = sums.max;
  m.knots_uncovered = sums.uncovered;
  m.knot_rms = n > sums.uncovered ? std::sqrt(sums.sum2 / double(n - sums.uncovered)) : 0;
}

}  // namespace

Measured measure(const Input& in, const Run& run, const Options& o) {
  Measured m;
  const MeshView view = run.result.view();
  const SurfaceSamples samples = sample_surface(view, o.samples, 12);
  const TriangleTree tree(view);
  m.error = two_sided_error(in.samples, *in.tree, samples, tree);
  if (in.height) {
    vertical_error(in, samples, m);
    knot_error(in, run.result, m);
  }
  isoform_mesh* mesh = nullptr;
  if (view.triangle_count > 0 &&
      isoform_mesh_from_arrays_f64(view.points, view.vertex_count, view.triangles, view.triangle_count, &mesh) ==
          ISOFORM_OK) {
    isoform_mesh_stats_get(mesh, &m.stats);
    isoform_mesh_free(mesh);
  }
  return m;
}

}  // namespace isoform_reduce_bench
