// isoform's reduction through its C API, as users call it: a mesh handle
// from the double-precision arrays (not timed, as the peers' own mesh
// structures are not), then isoform_reduce in place to the same triangle
// target as the peers. The curvature it needs is computed inside the call,
// so its time is included. Where the peers lock the boundary vertices,
// isoform keeps a graph's domain covered with its graph option (boundary
// points may go, along the straight boundary lines), or, with
// --isoform-lock-boundary, never removes a triangle that touches the border.
#include <cmath>
#include <ctime>
#include <stdexcept>

#include "reduce_bench.h"

namespace isoform_reduce_bench {

double process_cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void check(isoform_status status, const char* what) {
  if (status != ISOFORM_OK) throw std::runtime_error(std::string(what) + ": " + isoform_last_error());
}

#ifdef ISOFORM_BENCH_HAVE_REDUCE

bool isoform_reduce_available() { return true; }

Run run_isoform(const Input& in, double percent, const Options& o) {
  Run r;
  r.method = "isoform";
  r.percent = percent;
  const size_t m = in.mesh.triangle_count();
  r.target = size_t(std::llround(double(m) * (1 - percent / 100)));
  isoform_reduce_options ro;
  isoform_reduce_options_default(&ro);
  ro.keep_fraction = double(r.target) / double(m);
  ro.graph = o.lock_boundary && in.height && !o.isoform_lock_boundary ? 1 : 0;
  ro.lock_boundary = o.lock_boundary && (!in.height || o.isoform_lock_boundary) ? 1 : 0;
  r.time.wall = r.time.cpu = INFINITY;
  for (int rep = 0; rep < o.reps; ++rep) {
    isoform_mesh* mesh = nullptr;
    check(isoform_mesh_from_arrays_f64(in.mesh.points.data(), in.mesh.vertex_count(), in.mesh.triangles.data(), m, &mesh),
          "isoform_mesh_from_arrays_f64");
    isoform_status st = ISOFORM_OK;
    const Timing t = timed([&] { st = isoform_reduce(mesh, &ro, nullptr); });
    if (st != ISOFORM_OK) {
      r.failure = std::string("isoform_reduce: ") + isoform_last_error();
      isoform_mesh_free(mesh);
      return r;
    }
    r.time.wall = std::min(r.time.wall, t.wall);
    r.time.cpu = std::min(r.time.cpu, t.cpu);
    if (rep + 1 == o.reps) {
      std::vector<float> points(3 * isoform_mesh_vertex_count(mesh));
      Surface s;
      s.triangles.resize(3 * isoform_mesh_triangle_count(mesh));
      check(isoform_mesh_copy_points(mesh, points.data()), "isoform_mesh_copy_points");
      check(isoform_mesh_copy_triangles(mesh, s.triangles.data()), "isoform_mesh_copy_triangles");
      s.points.assign(points.begin(), points.end());
      r.result = compact(s);
    }
    isoform_mesh_free(mesh);
  }
  r.extra = Json{{"keep_fraction", ro.keep_fraction}, {"lock_boundary", ro.lock_boundary}, {"graph", ro.graph},
                 {"point_method", ro.point_method}, {"swaps", ro.swaps}};
  return r;
}

#else

bool isoform_reduce_available() { return false; }

Run run_isoform(const Input&, double percent, const Options&) {
  Run r;
  r.method = "isoform";
  r.percent = percent;
  r.failure = "isoform_reduce is not in this build's isoform.h";
  return r;
}

#endif

}  // namespace isoform_reduce_bench
