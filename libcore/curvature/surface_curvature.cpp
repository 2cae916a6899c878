// The Section 4.2 driver: every vertex in parallel, results into the mesh.
#include "surface_curvature.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include "../errors.h"
#include "../fresh_memory.h"
#include "../topology.h"
#include "seed_vertex.h"
#include "vertex_fit.h"

namespace isoform {
namespace {

constexpr size_t kGrain = 4096;

void store(VertexCurvature& c, size_t v, const VertexFitResult& r) {
  const PrincipalCurvatures& p = r.curvature;
  c.k1[v] = float(p.k1);
  c.k2[v] = float(p.k2);
  c.mean[v] = float(p.mean());
  c.gauss[v] = float(p.gauss());
  c.absolute[v] = float(std::abs(p.k1) + std::abs(p.k2));
  for (int a = 0; a < 3; ++a) {
    c.d1[3 * v + size_t(a)] = float(p.d1(a));
    c.d2[3 * v + size_t(a)] = float(p.d2(a));
  }
  c.flags[v] = r.flags;
}

// store() for four results side by side (vertices first .. first + 3):
// the same conversions (each lane's operations are store's), four values to
// an instruction.
void store_lanes(VertexCurvature& c, size_t first, const SeedLanes& r) {
  typedef double Doubles __attribute__((vector_size(32)));
  typedef float Floats __attribute__((vector_size(16)));
  typedef int64_t Bits __attribute__((vector_size(32)));
  auto put = [](float* out, Doubles x) {
    const Floats f = __builtin_convertvector(x, Floats);
    std::memcpy(out, &f, sizeof(f));
  };
  Doubles k1, k2;
  std::memcpy(&k1, r.k1, sizeof(k1));
  std::memcpy(&k2, r.k2, sizeof(k2));
  const Bits magnitude = {INT64_MAX, INT64_MAX, INT64_MAX, INT64_MAX};  // std::abs: the sign bit cleared
  put(&c.k1[first], k1);
  put(&c.k2[first], k2);
  put(&c.mean[first], 0.5 * (k1 + k2));
  put(&c.gauss[first], k1 * k2);
  put(&c.absolute[first], (Doubles)((Bits)k1 & magnitude) + (Doubles)((Bits)k2 & magnitude));
  // x y z of the four directions one after another: twelve values.
  auto put_directions = [&](float* out, const double (&d)[3][4]) {
    put(out, Doubles{d[0][0], d[1][0], d[2][0], d[0][1]});
    put(out + 4, Doubles{d[1][1], d[2][1], d[0][2], d[1][2]});
    put(out + 8, Doubles{d[2][2], d[0][3], d[1][3], d[2][3]});
  };
  put_directions(&c.d1[3 * first], r.d1);
  put_directions(&c.d2[3 * first], r.d2);
  for (int i = 0; i < 4; ++i) c.flags[first + size_t(i)] = r.flags[i];
}

// A group of four results one by one, put side by side for store_lanes.
void store_four(VertexCurvature& c, size_t first, const VertexFitResult* r) {
  SeedLanes lanes;
  for (int l = 0; l < 4; ++l) {
    const PrincipalCurvatures& p = r[l].curvature;
    lanes.k1[l] = p.k1;
    lanes.k2[l] = p.k2;
    for (int a = 0; a < 3; ++a) {
      lanes.d1[a][l] = p.d1(a);
      lanes.d2[a][l] = p.d2(a);
    }
    lanes.flags[l] = r[l].flags;
  }
  store_lanes(c, first, lanes);
}

// NOTE: a triangle without area has no normal and no plane: the fits
// around it divide by zero and yield NaN. The reduction refuses such meshes
// at entry; so does the curvature, naming the first offender, rather than
// return values that are not numbers.
void require_fittable(const Mesh& mesh) {
  for (size_t i = 0; i < mesh.points.size(); ++i)
    if (!std::isfinite(mesh.points[i]))
      throw InvalidArgument("curvature: vertex " + std::to_string(i / 3) +
                            " has a coordinate that is not finite (NaN or infinity)");
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (!is_degenerate_triangle(mesh, t)) continue;
    const int32_t* v = &mesh.triangles[3 * t];
    const std::string corners = " (" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " +
                                std::to_string(v[2]) + ")";
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
      throw InvalidArgument("curvature: triangle " + std::to_string(t) + " uses a vertex twice" + corners);
    throw InvalidArgument("curvature: triangle " + std::to_string(t) + corners +
                          " has no area at the precision of its coordinates");
  }
}

}  // namespace

void compute_curvature(const Mesh& mesh, const CurvatureOptions& options, const Progress& progress,
                       VertexCurvature& c, std::vector<float>* fitted) {
  const size_t n = mesh.vertex_count();
  require_fittable(mesh);
  if (options.extra_rings < 0 || options.extra_rings > 8)
    throw InvalidArgument("curvature: extra rings must be 0 to 8, not " + std::to_string(options.extra_rings));
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.points.size())
    throw InvalidArgument("curvature: the mesh has " + std::to_string(mesh.normals.size() / 3) + " normals for " +
                          std::to_string(n) + " vertices");
  const VertexRings rings(mesh);
  c.stats = CurvatureStats{};
  c.stats.method = options.method;
  // Arrays that already have the size are kept (no new pages); new ones get
  // their pages present, in 2 MB pages where the system allows, before the
  // fits write them (fresh_memory.h).
  auto sized = [](auto& a, size_t count) {
    if (a.size() == count) return;
    a.clear();
    a.shrink_to_fit();
    fresh_resize(a, count, false, true);
  };
  for (auto* a : {&c.k1, &c.k2, &c.mean, &c.gauss, &c.absolute}) sized(*a, n);
  sized(c.d1, 3 * n);
  sized(c.d2, 3 * n);
  sized(c.flags, n);
  std::vector<float> unused;
  std::vector<float>& fitted_normals = options.update_normals && fitted ? *fitted : unused;
  fitted_normals.assign(options.update_normals && fitted ? 3 * n : 0, 0.0f);
  // The seed's method on its one-ring takes the short path (seed_vertex.h).
  const bool seed = options.method == CurvatureMethod::Seed && options.extra_rings == 0;
  tbb::enumerable_thread_specific<VertexFitScratch> scratch;
  std::atomic<size_t> done{0};
  std::atomic<bool> stop{false};
  auto keep = [&](size_t v, const VertexFitResult& r) {
    store(c, v, r);
    if (fitted_normals.empty()) return;
    if (!(r.flags & (kCurvatureIsolated | kCurvatureFailed)))
      for (int a = 0; a < 3; ++a) fitted_normals[3 * v + size_t(a)] = float(r.curvature.normal(a));
    else if (mesh.normals.size() == 3 * n)
      for (int a = 0; a < 3; ++a) fitted_normals[3 * v + size_t(a)] = mesh.normals[3 * v + size_t(a)];
  };
  auto body = [&](const tbb::blocked_range<size_t>& range) {
    if (stop.load(std::memory_order_relaxed)) return;
    if (progress.cancelled()) {
      stop = true;
      return;
    }
    VertexFitScratch& s = scratch.local();
    // Four vertices at a time (fit_seed_vertices) or eight (fit_vertices);
    // each result is the one the one-vertex fit gives, so the grouping
    // cannot change a bit.
    VertexFitResult group[8], four[4];
    SeedLanes lanes;
    SeedLanes* const as_lanes = fitted_normals.empty() ? &lanes : nullptr;
    const size_t step = seed ? 4 : 8;
    for (size_t first = range.begin(); first < range.end(); first += step) {
      const int count = int(std::min<size_t>(step, range.end() - first));
      if (seed) {
        if (fit_seed_vertices(mesh, rings, int32_t(first), count, s, four, as_lanes)) {
          store_lanes(c, first, lanes);
          continue;
        }
        std::copy(four, four + count, group);
      } else {
        fit_vertices(mesh, rings, int32_t(first), count, options.method, options.extra_rings, s, group);
      }
      for (int k = 0; k < count; k += 4) {
        if (count - k == 4 && fitted_normals.empty())
          store_four(c, first + size_t(k), group + k);
        else
          for (int i = k; i < std::min(count, k + 4); ++i) keep(first + size_t(i), group[i]);
      }
    }
    progress.fraction(float(done.fetch_add(range.size()) + range.size()) / float(n));
  };
  const tbb::blocked_range<size_t> all(0, n, kGrain);
  if (options.threads == 1) {
    for (size_t b = 0; b < n; b += kGrain) body(tbb::blocked_range<size_t>(b, std::min(n, b + kGrain)));
  } else if (options.threads > 1) {
    tbb::task_arena arena(options.threads);
    arena.execute([&] { tbb::parallel_for(all, body); });
  } else {
    tbb::parallel_for(all, body);
  }
  if (stop) throw Cancelled("curvature: cancelled");
  count_curvature_flags(c);
}

void compute_curvature(Mesh& mesh, const CurvatureOptions& options, const Progress& progress) {
  VertexCurvature c;
  std::vector<float> fitted;
  compute_curvature(mesh, options, progress, c, &fitted);
  mesh.curvature = std::move(c);
  if (options.update_normals) mesh.normals = std::move(fitted);
}

const char* curvature_method_name(CurvatureMethod method) {
  switch (method) {
    case CurvatureMethod::Seed: return "seed";
    case CurvatureMethod::Quadric: return "quadric";
    case CurvatureMethod::Cubic: return "cubic";
    case CurvatureMethod::Quartic: return "quartic";
  }
  return "unknown";
}

bool parse_curvature_method(const char* name, CurvatureMethod* out) {
  for (CurvatureMethod m : {CurvatureMethod::Seed, CurvatureMethod::Quadric, CurvatureMethod::Cubic,
                            CurvatureMethod::Quartic})
    if (name && std::strcmp(name, curvature_method_name(m)) == 0) {
      *out = m;
      return true;
    }
  return false;
}

}  // namespace isoform
