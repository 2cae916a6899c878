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

// A method's round on one handle: the best of reps calls per thread count
// (after one untimed call in the first round), kept in r where better than
// earlier rounds'; errors from the two-thread result of the first round.
void measure(const Case& c, isoform_mesh* m, int method, int reps, bool first_round, Result& r) {
  isoform_curvature_options o;
  isoform_curvature_options_default(&o);
  o.method = method;
  auto call = [&](int threads) {
    o.threads = threads;
    check(isoform_curvature(m, &o, nullptr), "isoform_curvature");
  };
  if (first_round) call(1);
  const Timing one = best_of(reps, [&] { call(1); });
  const Curvatures by_one = copy_curvatures(m);
  const Timing two = best_of(reps, [&] { call(2); });
  const Curvatures by_two = copy_curvatures(m);
  r.same_bits = r.same_bits && same_bits(by_one, by_two);
  if (first_round) {
    r.one = one;
    r.two = two;
    r.rms = rms_of(c, by_two);
    isoform_curvature_stats s;
    check(isoform_mesh_curvature_stats(m, &s), "isoform_mesh_curvature_stats");
    r.extra = Json{{"widened", s.widened}, {"lower_order", s.lower_order}, {"failed", s.failed},
                   {"normal_repaired", s.normal_repaired}};
    return;
  }
  r.one = better(r.one, one);
  r.two = better(r.two, two);
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
  // The four rows' calls in turn, round after round: a slow minute of the
  // shared machine then falls on one round of every method, not on all
  // calls of one.
  struct Row {
    isoform_mesh* mesh;
    int method;
    const char* name;
    bool estimated;
  };
  const Row rows[] = {{estimated.get(), ISOFORM_CURVATURE_QUARTIC, "isoform quartic (default)", true},
                      {given.get(), ISOFORM_CURVATURE_QUARTIC, "isoform quartic, exact normals", false},
                      {estimated.get(), ISOFORM_CURVATURE_SEED, "isoform seed", true},
                      {given.get(), ISOFORM_CURVATURE_SEED, "isoform seed, exact normals", false}};
  std::vector<Result> results(4);
  for (int round = 0; round < o.rounds; ++round)
    for (size_t i = 0; i < 4; ++i) measure(c, rows[i].mesh, rows[i].method, o.reps, round == 0, results[i]);
  for (size_t i = 0; i < 4; ++i) {
    results[i].method = rows[i].name;
    if (rows[i].estimated) {
      results[i].setup_seconds = handle_seconds;
      results[i].setup_what = setup;
    }
    out.push_back(results[i]);
  }
}

}  // namespace isoform_curvature_bench
