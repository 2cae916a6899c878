// The curvature step shared by `curvature` and `contour --curvature`.
#include "curvature_step.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace isoform::cli {
namespace {

const char* const kMethods[] = {"seed", "quadric", "cubic", "quartic"};
const char* const kQuantities[] = {"k1", "k2", "mean", "gauss", "absolute"};

int index_of(const char* const* names, int count, const std::string& name) {
  for (int i = 0; i < count; ++i)
    if (name == names[i]) return i;
  return -1;
}

std::vector<float> values(const isoform_mesh* mesh, int quantity) {
  std::vector<float> v(isoform_mesh_vertex_count(mesh));
  check(isoform_mesh_copy_curvature(mesh, quantity, v.data()));
  return v;
}

// min, max, mean and the 2nd, 25th, 50th, 75th, 98th percentiles.
Json summary(std::vector<float> v) {
  if (v.empty()) return Json::object();
  double sum = 0;
  for (float x : v) sum += x;
  std::sort(v.begin(), v.end());
  auto pct = [&](double p) { return double(v[size_t(std::lround(p * double(v.size() - 1)))]); };
  return Json{{"min", v.front()}, {"max", v.back()},  {"mean", sum / double(v.size())},
              {"p2", pct(0.02)},  {"p25", pct(0.25)}, {"p50", pct(0.5)},
              {"p75", pct(0.75)}, {"p98", pct(0.98)}};
}

}  // namespace

void add_curvature_options(CLI::App& app, CurvatureSettings& s, const std::string& method_flag) {
  app.add_option(method_flag, s.method,
                 "Curvature fit: seed (the dissertation's 3-term one-ring fit), quadric, cubic, or "
                 "quartic (default, the most accurate measured)")
      ->check(CLI::IsMember({"seed", "quadric", "cubic", "quartic"}));
  app.add_option("--rings", s.extra_rings, "Rings added to the fit's platelet, 0-8 (smooths noisy meshes)")
      ->check(CLI::Range(0, 8));
  app.add_option("--color-by", s.color_by, "Quantity the vertex colours show: k1, k2, mean (default), gauss, absolute")
      ->check(CLI::IsMember({"k1", "k2", "mean", "gauss", "absolute"}));
  app.add_flag("--fit-normals", s.update_normals, "Replace the mesh's normals by the fitted surface's");
}

double compute_curvature(isoform_mesh* mesh, const CurvatureSettings& s, int threads,
                         const ProgressOptions& progress) {
  isoform_curvature_options o;
  isoform_curvature_options_default(&o);
  o.method = index_of(kMethods, 4, s.method);
  o.extra_rings = s.extra_rings;
  o.color_by = index_of(kQuantities, 5, s.color_by);
  o.update_normals = s.update_normals ? 1 : 0;
  o.threads = threads;
  const auto start = std::chrono::steady_clock::now();
  run_with_progress([&](isoform_progress* p) { return isoform_curvature(mesh, &o, p); }, progress);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Json curvature_json(const isoform_mesh* mesh) {
  isoform_curvature_stats s;
  check(isoform_mesh_curvature_stats(mesh, &s));
  Json j = {{"method", kMethods[s.method]}, {"vertices", s.vertices}};
  for (int q = 0; q < 5; ++q) j[kQuantities[q]] = summary(values(mesh, q));
  j["fallbacks"] = {{"boundary", s.boundary},       {"widened", s.widened},
                    {"lower_order", s.lower_order}, {"nonmanifold", s.nonmanifold},
                    {"isolated", s.isolated},       {"failed", s.failed},
                    {"normal_repaired", s.normal_repaired}};
  j["colors"] = {{"quantity", kQuantities[s.color_by]}, {"min", s.color_min}, {"max", s.color_max}};
  return j;
}

void print_curvature(std::ostream& out, const isoform_mesh* mesh) {
  const Json j = curvature_json(mesh);
  print_row(out, "curvature", std::string(j["method"]) + " fit");
  for (const char* q : kQuantities) {
    const Json& s = j[q];
    if (s.empty()) continue;
    print_row(out, q,
              "median " + format_number(s["p50"]) + ", 2-98% [" + format_number(s["p2"]) + ", " +
                  format_number(s["p98"]) + "], range [" + format_number(s["min"]) + ", " +
                  format_number(s["max"]) + "]");
  }
  std::string fallbacks;
  for (const auto& [name, count] : j["fallbacks"].items())
    if (count.get<long long>() > 0)
      fallbacks += (fallbacks.empty() ? "" : ", ") + std::to_string(count.get<long long>()) + " " + name;
  print_row(out, "fallbacks", fallbacks.empty() ? "none" : fallbacks);
  print_row(out, "colours", std::string(j["colors"]["quantity"]) + " over [" +
                                format_number(j["colors"]["min"]) + ", " + format_number(j["colors"]["max"]) + "]");
}

}  // namespace isoform::cli
