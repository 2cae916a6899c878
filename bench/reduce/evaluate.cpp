// What each result is measured by: the two-sided sampled distance to the
// original (metro.h), for a graph also the vertical distance to its
// function at the same samples, and isoform's mesh statistics of the result
// (boundary and non-manifold edges, Euler characteristic, parts).
#include <algorithm>
#include <cmath>

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

}  // namespace

Measured measure(const Input& in, const Run& run, const Options& o) {
  Measured m;
  const MeshView view = run.result.view();
  const SurfaceSamples samples = sample_surface(view, o.samples, 12);
  const TriangleTree tree(view);
  m.error = two_sided_error(in.samples, *in.tree, samples, tree);
  if (in.height) vertical_error(in, samples, m);
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
