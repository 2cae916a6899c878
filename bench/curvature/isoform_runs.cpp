// isoform's surface curvature through its C API, as users call it: a mesh
// handle from double-precision arrays (normals estimated from the mesh,
// Remark 3.15), or the same with the exact normals set, then
// isoform_curvature with one thread and with two.
#include <cstring>
#include <memory>
#include <stdexcept>

#include "curvature_bench.h"

namespace isoform_curvature_bench {
namespace {

using MeshPtr = std::unique_ptr<isoform_mesh, void (*)(isoform_mesh*)>;

Curvatures copy_curvatures(const isoform_mesh* m) {
  const size_t n = isoform_mesh_vertex_count(m);
  Curvatures r;
  for (auto* v : {&r.k1, &r.k2, &r.mean, &r.gauss}) v->resize(n);
  check(isoform_mesh_copy_curvature(m, ISOFORM_CURVATURE_K1, r.k1.data()), "copy k1");
  check(isoform_mesh_copy_curvature(m, ISOFORM_CURVATURE_K2, r.k2.data()), "copy k2");
  check(isoform_mesh_copy_curvature(m, ISOFORM_CURVATURE_MEAN, r.mean.data()), "copy mean");
  check(isoform_mesh_copy_curvature(m, ISOFORM_CURVATURE_GAUSS, r.gauss.data()), "copy gauss");
  return r;
}

bool same_bits(const Curvatures& a, const Curvatures& b) {
  auto eq = [](const std::vector<float>& x, const std::vector<float>& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(float)) == 0;
  };
  return eq(a.k1, b.k1) && eq(a.k2, b.k2) && eq(a.mean, b.mean) && eq(a.gauss, b.gauss);
}

// One method on one handle: the best of reps calls per thread count (after
// one untimed call), errors from the two-thread result.
Result measure(const Case& c, isoform_mesh* m, int method, const char* name, int reps) {
  Result r;
  r.method = name;
  isoform_curvature_options o;
  isoform_curvature_options_default(&o);
  o.method = method;
  auto call = [&](int threads) {
    o.threads = threads;
    check(isoform_curvature(m, &o, nullptr), "isoform_curvature");
  };
  call(1);
  r.one = best_of(reps, [&] { call(1); });
  const Curvatures one = copy_curvatures(m);
  r.two = best_of(reps, [&] { call(2); });
  const Curvatures two = copy_curvatures(m);
  r.same_bits = same_bits(one, two);
  r.rms = rms_of(c, two);
  isoform_curvature_stats s;
  check(isoform_mesh_curvature_stats(m, &s), "isoform_mesh_curvature_stats");
  r.extra = Json{{"widened", s.widened}, {"lower_order", s.lower_order}, {"failed", s.failed},
                 {"normal_repaired", s.normal_repaired}};
  return r;
}

}  // namespace

void run_isoform(const Case& c, const Options& o, std::vector<Result>& out, std::vector<float>& mesh_normals) {
  const size_t n = c.vertex_count(), m = c.triangles.size() / 3;
  isoform_mesh* raw = nullptr;
  // The handle's construction (neighbours, parts, normals estimated on the
  // one-ring) is timed apart: the curvature calls then reuse its normals.
  const Clock::time_point t = Clock::now();
  check(isoform_mesh_from_arrays_f64(c.points.data(), n, c.triangles.data(), m, &raw), "isoform_mesh_from_arrays_f64");
  const double handle_seconds = seconds_since(t);
  MeshPtr estimated(raw, isoform_mesh_free);
  mesh_normals.resize(3 * n);
  check(isoform_mesh_copy_normals(estimated.get(), mesh_normals.data()), "isoform_mesh_copy_normals");

  check(isoform_mesh_from_arrays_f64(c.points.data(), n, c.triangles.data(), m, &raw), "isoform_mesh_from_arrays_f64");
  MeshPtr given(raw, isoform_mesh_free);
  check(isoform_mesh_set_normals(given.get(), c.exact_normals.data()), "isoform_mesh_set_normals");

  const char* setup = "isoform_mesh_from_arrays_f64 (topology, normals estimated), all cores";
  Result q = measure(c, estimated.get(), ISOFORM_CURVATURE_QUARTIC, "isoform quartic (default)", o.reps);
  q.setup_seconds = handle_seconds;
  q.setup_what = setup;
  out.push_back(q);
  out.push_back(measure(c, given.get(), ISOFORM_CURVATURE_QUARTIC, "isoform quartic, exact normals", o.reps));
  Result s = measure(c, estimated.get(), ISOFORM_CURVATURE_SEED, "isoform seed", o.reps);
  s.setup_seconds = handle_seconds;
  s.setup_what = setup;
  out.push_back(s);
  out.push_back(measure(c, given.get(), ISOFORM_CURVATURE_SEED, "isoform seed, exact normals", o.reps));
}

}  // namespace isoform_curvature_bench
