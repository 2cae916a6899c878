// The error guard of graph mode (docs/reduce.md, "Error guard"): no removal
// takes a knot far past the typical error of the knots moved so far, so the
// largest knot error of a reduced graph stays within a few times the RMS
// (without the guard the eight curved graphs at 90 % reach 4.7 to 8.1 times it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "table51.h"

namespace isoform {
namespace {

double coord(const Mesh& m, size_t v, int k) {
  return m.precise_points.size() == m.points.size() ? m.precise_points[3 * v + size_t(k)]
                                                    : double(m.points[3 * v + size_t(k)]);
}

// The largest height error at the original knots (each in the reduced
// triangle above it, by brute force) and the RMS.
void knot_errors(const Mesh& original, const Mesh& reduced, double* max, double* rms) {
  double sum = 0;
  *max = 0;
  for (size_t v = 0; v < original.vertex_count(); ++v) {
    const double x = coord(original, v, 0), y = coord(original, v, 1);
    double best = -std::numeric_limits<double>::infinity(), z = 0;
    for (size_t t = 0; t < reduced.triangle_count(); ++t) {
      double px[3], py[3], pz[3];
      for (int k = 0; k < 3; ++k) {
        const size_t i = size_t(reduced.triangles[3 * t + size_t(k)]);
        px[k] = coord(reduced, i, 0);
        py[k] = coord(reduced, i, 1);
        pz[k] = coord(reduced, i, 2);
      }
      const double det = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
      if (!(std::abs(det) > 0)) continue;
      const double l1 = ((x - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (y - py[0])) / det;
      const double l2 = ((px[1] - px[0]) * (y - py[0]) - (x - px[0]) * (py[1] - py[0])) / det;
      const double inside = std::min({1 - l1 - l2, l1, l2});
      if (inside > best) {
        best = inside;
        z = (1 - l1 - l2) * pz[0] + l1 * pz[1] + l2 * pz[2];
      }
    }
    const double e = std::abs(coord(original, v, 2) - z);
    *max = std::max(*max, e);
    sum += e * e;
  }
  *rms = std::sqrt(sum / double(original.vertex_count()));
}

TEST(ReduceGuard, GraphKnotMaximumStaysNearTheRms) {
  const auto& graphs = truth::table41_graphs();
  for (size_t i = 1; i < graphs.size(); ++i) {
    const Mesh original = truth::graph_mesh(graphs[i], 81);
    Mesh mesh = original;
    ReduceOptions options;
    options.graph = true;
    options.keep_fraction = 0.1;
    reduce_mesh(mesh, options, Progress(nullptr));
    double max = 0, rms = 0;
    knot_errors(original, mesh, &max, &rms);
    EXPECT_GT(rms, 0) << graphs[i].name;
    EXPECT_LE(max, 5.0 * rms) << graphs[i].name << ": max " << max << ", RMS " << rms;
  }
}

}  // namespace
}  // namespace isoform
