// bench/patch-vs-loop: points per second of the side-vertex surface
// (Chapter 6, libcore/patch) against OpenSubdiv's Loop limit surface
// (libcore/compare), on the same mesh and the same samples, in one run.
//
// usage: isoform_patch_vs_loop_bench MESH.ply [--level K] [--reps N] [--json FILE]
//
// Every base triangle is sampled at the lattice (i/k, j/k), i + j <= k;
// each evaluation returns the point, the unit normal and first and second
// derivatives (SurfaceSample), single-threaded. CPU time of this thread
// (clock_gettime(CLOCK_THREAD_CPUTIME_ID)), so load on the machine costs less. Repetitions alternate the
// surfaces (A B A B ...) so that load on the shared machine hits both alike;
// the best and the median of each are reported, and their ratio. Building
// each surface (OpenSubdiv's adaptive refinement and patch table; the
// side-vertex surface's edge curves) is timed apart. The side-vertex surface's
// reference path (SideVertexSurface::evaluate_reference, the construction in
// two-variable jets) runs alongside, for the fast path's speed-up.
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "libcore/compare/lattice.h"
#include "libcore/compare/loop_surface.h"
#include "libcore/meshio/meshio.h"
#include "libcore/mesh_normals.h"
#include "libcore/patch/batch_eval.h"
#include "libcore/patch/side_vertex_surface.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// One pass over every lattice sample; returns its CPU seconds. The checksum
// keeps the compiler from dropping the evaluations.
double sample_pass(const isoform::TriangleSurface& s, const std::vector<isoform::compare::LatticePoint>& lattice,
                   double& checksum, long long& failed) {
  isoform::SurfaceSample x;
  const double start = thread_cpu_seconds();
  for (size_t t = 0; t < s.triangle_count(); ++t)
    for (const auto& p : lattice) {
      if (s.evaluate(t, p.u, p.v, x)) checksum += x.point[0] + x.normal[2] + x.duu[1];
      else ++failed;
    }
  return thread_cpu_seconds() - start;
}

// The same pass through the side-vertex surface's batch entry point
// (batch_eval.h): each triangle's lattice in one call, with one plan of the
// lattice (which samples share a ray) made inside the timed pass.
double batch_pass(const isoform::patch::SideVertexSurface& s, const std::vector<double>& u,
                  const std::vector<double>& v, bool second, double& checksum, long long& failed) {
  std::vector<isoform::SurfaceSample> out(u.size());
  std::unique_ptr<bool[]> ok(new bool[u.size()]);
  const double start = thread_cpu_seconds();
  const isoform::patch::BatchPlan plan(s.options(), u.data(), v.data(), u.size());
  for (size_t t = 0; t < s.triangle_count(); ++t) {
    isoform::patch::evaluate_batch(s, t, plan, out.data(), ok.get(), second);
    for (size_t k = 0; k < u.size(); ++k) {
      if (ok[k]) checksum += out[k].point[0] + out[k].normal[2] + out[k].duu[1];
      else ++failed;
    }
  }
  return thread_cpu_seconds() - start;
}

// The side-vertex surface by its reference path (the whole construction in
// two-variable jets), the evaluation before the fast path.
class ReferencePath final : public isoform::TriangleSurface {
 public:
  explicit ReferencePath(std::unique_ptr<isoform::patch::SideVertexSurface> s) : s_(std::move(s)) {}
  size_t triangle_count() const override { return s_->triangle_count(); }
  bool evaluate(size_t t, double u, double v, isoform::SurfaceSample& out) const override {
    return s_->evaluate_reference(t, u, v, out, true);
  }

 private:
  std::unique_ptr<isoform::patch::SideVertexSurface> s_;
};

struct Run {
  std::string name;
  double build_seconds = 0.0;
  std::vector<double> seconds;
  long long failed = 0;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Side-vertex surface against OpenSubdiv Loop: points per second, same mesh and samples"};
  std::string input, json_path;
  int level = 8, reps = 5;
  app.add_option("mesh", input, "Base mesh (.ply with normals, .obj, .stl)")->required();
  app.add_option("--level", level, "Lattice level k: (k+1)(k+2)/2 samples per triangle")->check(CLI::Range(1, 64));
  app.add_option("--reps", reps, "Timed passes per surface")->check(CLI::Range(1, 100));
  app.add_option("--json", json_path, "Also write the figures as JSON here");
  CLI11_PARSE(app, argc, argv);

  isoform::Mesh mesh = isoform::load_mesh(input);
  if (mesh.normals.size() != mesh.points.size()) isoform::estimate_normals(mesh);
  std::string error;
  constexpr int kSurfaces = 4;
  std::vector<Run> runs(kSurfaces);
  std::vector<std::unique_ptr<isoform::TriangleSurface>> surfaces(kSurfaces);
  const std::function<std::unique_ptr<isoform::TriangleSurface>()> makers[kSurfaces] = {
      [&] { return isoform::patch::make_side_vertex_surface(mesh, {}, error); },
      [&] {
        isoform::patch::PatchOptions o;
        o.second_derivatives = false;
        return isoform::patch::make_side_vertex_surface(mesh, o, error);
      },
      [&] { return isoform::compare::make_loop_surface(mesh, {}, error); },
      [&]() -> std::unique_ptr<isoform::TriangleSurface> {
        try {
          return std::make_unique<ReferencePath>(std::make_unique<isoform::patch::SideVertexSurface>(mesh,
                                                                                                     isoform::patch::PatchOptions{}));
        } catch (const std::exception& e) {
          error = e.what();
          return nullptr;
        }
      }};
  const char* names[kSurfaces] = {"side-vertex", "side-vertex, no second derivatives", "loop (OpenSubdiv)",
                                  "side-vertex, reference path"};
  for (int i = 0; i < kSurfaces; ++i) {
    runs[size_t(i)].name = names[i];
    const auto start = Clock::now();
    surfaces[size_t(i)] = makers[i]();
    runs[size_t(i)].build_seconds = seconds_since(start);
    if (!surfaces[size_t(i)]) {
      std::cerr << input << ": " << names[i] << ": " << error << '\n';
      return 1;
    }
  }
  const auto lattice = isoform::compare::lattice(level);
  const long long samples = (long long)mesh.triangle_count() * (long long)lattice.size();
  double checksum = 0.0;
  // Two more runs: the side-vertex surfaces 0 and 1 through the batch entry point.
  const auto* with_second = dynamic_cast<const isoform::patch::SideVertexSurface*>(surfaces[0].get());
  const auto* without_second = dynamic_cast<const isoform::patch::SideVertexSurface*>(surfaces[1].get());
  runs.push_back({"side-vertex, batch", runs[0].build_seconds, {}, 0});
  runs.push_back({"side-vertex, batch, no second derivatives", runs[1].build_seconds, {}, 0});
  std::vector<double> lu, lv;
  for (const auto& p : lattice) lu.push_back(p.u), lv.push_back(p.v);
  for (int r = 0; r < reps; ++r) {
    for (size_t i = 0; i < size_t(kSurfaces); ++i) {
      long long failed = 0;
      runs[i].seconds.push_back(sample_pass(*surfaces[i], lattice, checksum, failed));
      runs[i].failed = failed;
    }
    for (int b = 0; b < 2; ++b) {
      long long failed = 0;
      runs[size_t(kSurfaces + b)].seconds.push_back(
          batch_pass(b == 0 ? *with_second : *without_second, lu, lv, b == 0, checksum, failed));
      runs[size_t(kSurfaces + b)].failed = failed;
    }
  }

  nlohmann::ordered_json j = {{"mesh", input}, {"triangles", mesh.triangle_count()}, {"level", level},
                              {"samples", samples}, {"reps", reps}, {"checksum", checksum}};
  std::printf("%s: %zu triangles, level %d, %lld samples per pass, %d passes each (interleaved)\n",
              input.c_str(), mesh.triangle_count(), level, samples, reps);
  std::printf("%-36s %10s %14s %14s %8s\n", "surface", "build s", "best Mpts/s", "median Mpts/s", "failed");
  for (const Run& r : runs) {
    const double best = *std::min_element(r.seconds.begin(), r.seconds.end()), med = median(r.seconds);
    std::printf("%-36s %10.3f %14.3f %14.3f %8lld\n", r.name.c_str(), r.build_seconds, samples / best / 1e6,
                samples / med / 1e6, r.failed);
    j["surfaces"].push_back({{"name", r.name}, {"build_seconds", r.build_seconds}, {"pass_seconds", r.seconds},
                             {"best_points_per_second", samples / best}, {"median_points_per_second", samples / med},
                             {"failed", r.failed}});
  }
  const double ratio = median(runs[2].seconds) / median(runs[4].seconds);
  std::printf("side-vertex (batch) / Loop points per second (medians): %.2f (target >= 1)\n", ratio);
  j["side_vertex_over_loop"] = ratio;
  const double per_sample = median(runs[2].seconds) / median(runs[0].seconds);
  std::printf("side-vertex (one sample per call) / Loop points per second (medians): %.2f\n", per_sample);
  j["side_vertex_per_sample_over_loop"] = per_sample;
  const double speedup = median(runs[3].seconds) / median(runs[0].seconds);
  std::printf("side-vertex fast path / reference path (medians): %.2f\n", speedup);
  j["fast_over_reference"] = speedup;
  if (!json_path.empty()) std::ofstream(json_path) << j.dump(2) << '\n';
  return 0;
}
