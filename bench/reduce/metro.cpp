// Area-uniform sampling by inverting the cumulative area (which triangle)
// and the square-root map of the unit square onto a triangle (where in it);
// the sided errors as a parallel reduction over the samples.
#include "metro.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace isoform_reduce_bench {
namespace {

Vec3 vertex(const MeshView& m, size_t t, int i) {
  const double* p = m.points + 3 * size_t(m.triangles[3 * t + i]);
  return {p[0], p[1], p[2]};
}

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

struct Sums {
  double max = 0, sum = 0, sum2 = 0;
};

}  // namespace

SurfaceSamples sample_surface(const MeshView& mesh, size_t count, uint64_t seed) {
  SurfaceSamples s;
  const size_t m = mesh.triangle_count;
  std::vector<double> cumulative(m);
  double total = 0;
  for (size_t t = 0; t < m; ++t) {
    total += triangle_area(vertex(mesh, t, 0), vertex(mesh, t, 1), vertex(mesh, t, 2));
    cumulative[t] = total;
  }
  s.area = total;
  std::vector<char> used(mesh.vertex_count, 0);
  for (size_t t = 0; t < 3 * m; ++t) used[size_t(mesh.triangles[t])] = 1;
  const size_t used_count = size_t(std::count(used.begin(), used.end(), 1));
  s.points.reserve(3 * (count + used_count));
  if (total > 0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (size_t k = 0; k < count; ++k) {
      const double at = unit(rng) * total;
      const size_t t = std::min(size_t(std::upper_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin()), m - 1);
      const double r = std::sqrt(unit(rng)), q = unit(rng);
      const Vec3 a = vertex(mesh, t, 0), b = vertex(mesh, t, 1), c = vertex(mesh, t, 2);
      for (int i = 0; i < 3; ++i) s.points.push_back((1 - r) * a[i] + r * (1 - q) * b[i] + r * q * c[i]);
    }
    s.area_samples = count;
  }
  for (size_t v = 0; v < mesh.vertex_count; ++v)
    if (used[v]) s.points.insert(s.points.end(), mesh.points + 3 * v, mesh.points + 3 * v + 3);
  return s;
}

SidedError sided_error(const SurfaceSamples& from, const TriangleTree& to) {
  const auto distance = [&](size_t k) {
    const Vec3 p{from.points[3 * k], from.points[3 * k + 1], from.points[3 * k + 2]};
    return std::sqrt(to.distance2(p));
  };
  const Sums sums = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, from.count(), 1024), Sums{},
      [&](const tbb::blocked_range<size_t>& r, Sums acc) {
        for (size_t k = r.begin(); k != r.end(); ++k) {
          const double d = distance(k);
          acc.max = std::max(acc.max, d);
          if (k < from.area_samples) acc.sum += d, acc.sum2 += d * d;
        }
        return acc;
      },
      [](Sums a, const Sums& b) {
        a.max = std::max(a.max, b.max);
        a.sum += b.sum, a.sum2 += b.sum2;
        return a;
      });
  SidedError e;
  e.samples = from.count();
  e.max = from.count() ? sums.max : 0;
  if (from.area_samples) {
    e.mean = sums.sum / double(from.area_samples);
    e.rms = std::sqrt(sums.sum2 / double(from.area_samples));
  }
  return e;
}

TwoSidedError two_sided_error(const SurfaceSamples& a_samples, const TriangleTree& a_tree,
                              const SurfaceSamples& b_samples, const TriangleTree& b_tree) {
  return TwoSidedError{sided_error(a_samples, b_tree), sided_error(b_samples, a_tree)};
}

double bbox_diagonal(const MeshView& mesh) {
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = std::numeric_limits<double>::infinity(), hi[k] = -lo[k];
  for (size_t t = 0; t < 3 * mesh.triangle_count; ++t)
    for (int k = 0; k < 3; ++k) {
      const double x = mesh.points[3 * size_t(mesh.triangles[t]) + k];
      lo[k] = std::min(lo[k], x), hi[k] = std::max(hi[k], x);
    }
  if (mesh.triangle_count == 0) return 0;
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

}  // namespace isoform_reduce_bench
