// The reduction step (see reduce_step.h).
#include "reduce_step.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace isoform::cli {
namespace {

const char* kStopReasons[4] = {"target reached", "nothing more removable", "tolerance reached",
                               "RMS tolerance reached"};

isoform_reduce_stats stats_of(const isoform_mesh* mesh) {
  isoform_reduce_stats s;
  check(isoform_mesh_reduce_stats(mesh, &s));
  return s;
}

// Why each part was left alone (manifold parts only), one line each.
std::vector<std::string> left_alone(const isoform_mesh* mesh, const isoform_reduce_stats& s) {
  std::vector<std::string> lines;
  for (long long i = 0; i < s.parts_left_alone; ++i) {
    const char* why = isoform_mesh_reduce_left_alone(mesh, i);
    lines.push_back(why ? why : "");
  }
  return lines;
}

}  // namespace

double parse_share(const std::string& text, const std::string& flag) {
  const bool percent = !text.empty() && text.back() == '%';
  const std::string number = percent ? text.substr(0, text.size() - 1) : text;
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value))
    throw Failure(flag + ": '" + text + "' is not a fraction (write 10% or 0.1)");
  return percent ? value / 100.0 : value;
}

double parse_fraction(const std::string& text, const std::string& flag) {
  const double fraction = parse_share(text, flag);
  if (!(fraction > 0 && fraction <= 1))
    throw Failure(flag + ": '" + text + "' must lie in (0, 1], that is (0%, 100%]");
  return fraction;
}

double reduce_mesh(isoform_mesh* mesh, const ReduceSettings& s, const std::string& input,
                   const ProgressOptions& progress) {
  isoform_reduce_options o;
  isoform_reduce_options_default(&o);
  o.keep_fraction = s.keep_fraction;
  o.tolerance = s.tolerance;
  o.lock_boundary = s.lock_boundary ? 1 : 0;
  o.refine_point = s.refine_point ? 1 : 0;
  o.point_method = s.point == "quadric" ? ISOFORM_REDUCE_POINT_QUADRIC : ISOFORM_REDUCE_POINT_QUADRATIC;
  o.measure_error = 1;
  o.manifold_parts_only = s.manifold_parts ? 1 : 0;
  o.prevent_overlap = s.prevent_overlap ? 1 : 0;
  o.graph = s.graph ? 1 : 0;
  o.graph_rms_tolerance = s.rms_tolerance;
  const auto start = std::chrono::steady_clock::now();
  try {
    run_with_progress([&](isoform_progress* p) { return isoform_reduce(mesh, &o, p); }, progress);
  } catch (const Failure& failure) {
    const std::string message = failure.what(), library = "reduce: ";
    const bool named = message.compare(0, library.size(), library) == 0;
    throw Failure(input + ": " + (named ? message.substr(library.size()) : message), failure.exit_code());
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Json reduce_json(const isoform_mesh* mesh, double seconds) {
  const isoform_reduce_stats s = stats_of(mesh);
  return Json{{"triangles_before", s.triangles_before},
              {"triangles_after", s.triangles_after},
              {"vertices_before", s.vertices_before},
              {"vertices_after", s.vertices_after},
              {"removals", s.removals},
              {"swaps", s.swaps},
              {"vertex_points", s.vertex_points},
              {"kernel_points", s.kernel_points},
              {"passes", s.passes},
              {"curvature_computed", s.curvature_computed != 0},
              {"stop", kStopReasons[s.stop_reason & 3]},
              {"max_vertex_distance", s.max_distance},
              {"refused",
               {{"corona", s.refused_corona},
                {"half_plane", s.refused_half_plane},
                {"flip", s.refused_flip},
                {"nonmanifold", s.refused_nonmanifold},
                {"boundary", s.refused_boundary},
                {"tolerance", s.refused_tolerance},
                {"overlap", s.refused_overlap}}},
              {"parts_left_alone", s.parts_left_alone},
              {"triangles_left_alone", s.triangles_left_alone},
              {"left_alone", left_alone(mesh, s)},
              {"reduce_seconds", seconds}};
}

double graph_rms(const isoform_mesh* mesh) { return stats_of(mesh).graph_rms; }

void print_reduce(std::ostream& out, const isoform_mesh* mesh, double seconds) {
  const isoform_reduce_stats s = stats_of(mesh);
  print_row(out, "triangles", std::to_string(s.triangles_before) + " -> " + std::to_string(s.triangles_after));
  print_row(out, "vertices", std::to_string(s.vertices_before) + " -> " + std::to_string(s.vertices_after));
  print_row(out, "passes", std::to_string(s.passes) + " (" + kStopReasons[s.stop_reason & 3] + ")");
  if (s.parts_left_alone > 0) {
    print_row(out, "left alone", std::to_string(s.parts_left_alone) + " part(s), " +
                                     std::to_string(s.triangles_left_alone) + " triangle(s), unchanged");
    for (const std::string& why : left_alone(mesh, s)) out << "  " << why << '\n';
  }
  print_row(out, "max vertex distance", format_number(s.max_distance));
  print_row(out, "reduce time", format_seconds(seconds));
}

}  // namespace isoform::cli
