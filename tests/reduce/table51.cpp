// Table 5.1: measurement (see table51.h).
#include "table51.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isoform::table51 {

std::array<double, 3> seed_row(int function) {
  static const double rows[9][3] = {
      {0, 0, 0},
      {.000485, .000999, .002105},
      {.000445, .001234, .002288},
      {.000610, .001591, .003619},
      {.000248, .000794, .002009},
      {.000355, .000843, .001853},
      {.000381, .001029, .002160},
      {.000336, .000916, .002075},
      {.000359, .001088, .002054},
  };
  return {rows[function][0], rows[function][1], rows[function][2]};
}

namespace {

double point(const Mesh& m, size_t v, int k) {
  return m.precise_points.size() == m.points.size() ? m.precise_points[3 * v + size_t(k)]
                                                    : double(m.points[3 * v + size_t(k)]);
}

}  // namespace

double knot_rms(const Mesh& original, const Mesh& reduced) {
  const size_t nt = reduced.triangle_count();
  // Bounding boxes in (x, y) of the reduced triangles.
  std::vector<std::array<double, 4>> box(nt);
  for (size_t t = 0; t < nt; ++t) {
    box[t] = {1e300, -1e300, 1e300, -1e300};
    for (int k = 0; k < 3; ++k) {
      const size_t v = size_t(reduced.triangles[3 * t + size_t(k)]);
      box[t][0] = std::min(box[t][0], point(reduced, v, 0));
      box[t][1] = std::max(box[t][1], point(reduced, v, 0));
      box[t][2] = std::min(box[t][2], point(reduced, v, 1));
      box[t][3] = std::max(box[t][3], point(reduced, v, 1));
    }
  }
  double sum = 0;
  const double slack = 1e-9;
  for (size_t v = 0; v < original.vertex_count(); ++v) {
    const double x = point(original, v, 0), y = point(original, v, 1), z = point(original, v, 2);
    double best = -std::numeric_limits<double>::infinity(), best_z = 0;
    for (size_t t = 0; t < nt; ++t) {
      if (x < box[t][0] - slack || x > box[t][1] + slack || y < box[t][2] - slack || y > box[t][3] + slack)
        continue;
      const int32_t* tv = &reduced.triangles[3 * t];
      double px[3], py[3], pz[3];
      for (int k = 0; k < 3; ++k) {
        px[k] = point(reduced, size_t(tv[k]), 0);
        py[k] = point(reduced, size_t(tv[k]), 1);
        pz[k] = point(reduced, size_t(tv[k]), 2);
      }
      const double det = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
      if (!(std::abs(det) > 0)) continue;
      const double l1 = ((x - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (y - py[0])) / det;
      const double l2 = ((px[1] - px[0]) * (y - py[0]) - (x - px[0]) * (py[1] - py[0])) / det;
      const double inside = std::min({1 - l1 - l2, l1, l2});
      if (inside > best) {
        best = inside;
        best_z = (1 - l1 - l2) * pz[0] + l1 * pz[1] + l2 * pz[2];
      }
    }
    if (best < -1e-9) return std::numeric_limits<double>::infinity();
    sum += (z - best_z) * (z - best_z);
  }
  return std::sqrt(sum / double(original.vertex_count()));
}

Result measure(const truth::Graph& g, double removed, ReduceOptions options) {
  Mesh original = truth::graph_mesh(g, 51);
  Mesh mesh = original;
  options.graph = true;
  options.keep_fraction = 1.0 - removed;
  Result r;
  r.stats = reduce_mesh(mesh, options, Progress(nullptr));
  r.triangles_after = (long long)mesh.triangle_count();
  r.rms = knot_rms(original, mesh);
  return r;
}

}  // namespace isoform::table51
