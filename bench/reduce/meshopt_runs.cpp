// meshoptimizer's meshopt_simplify, the speed baseline: edge collapses with
// quadric error, the triangle target deciding (the relative error bound set
// to 1, the whole mesh's extent, so it never stops the collapses first), the
// border locked when the others' is. Float points, as the library takes
// them; converting them is not timed.
#include <cmath>

#include <meshoptimizer.h>

#include "reduce_bench.h"

namespace isoform_reduce_bench {

Run run_meshopt(const Input& in, double percent, const Options& o) {
  Run r;
  r.method = "meshoptimizer";
  r.percent = percent;
  const size_t m = in.mesh.triangle_count();
  r.target = size_t(std::llround(double(m) * (1 - percent / 100)));
  const std::vector<float> points(in.mesh.points.begin(), in.mesh.points.end());
  const std::vector<unsigned int> indices(in.mesh.triangles.begin(), in.mesh.triangles.end());
  std::vector<unsigned int> out(indices.size());
  size_t count = 0;
  float result_error = 0;
  r.time.wall = r.time.cpu = INFINITY;
  for (int rep = 0; rep < o.reps; ++rep) {
    const Timing t = timed([&] {
      count = meshopt_simplify(out.data(), indices.data(), indices.size(), points.data(), in.mesh.vertex_count(),
                               3 * sizeof(float), 3 * r.target, 1.0f,
                               o.lock_boundary ? unsigned(meshopt_SimplifyLockBorder) : 0u, &result_error);
    });
    r.time.wall = std::min(r.time.wall, t.wall);
    r.time.cpu = std::min(r.time.cpu, t.cpu);
  }
  Surface s;
  s.points = in.mesh.points;
  s.triangles.assign(out.begin(), out.begin() + std::ptrdiff_t(count));
  r.result = compact(s);
  r.extra = Json{{"result_error_relative", result_error},
                 {"result_error_absolute", result_error * meshopt_simplifyScale(points.data(), in.mesh.vertex_count(),
                                                                                3 * sizeof(float))}};
  return r;
}

}  // namespace isoform_reduce_bench
