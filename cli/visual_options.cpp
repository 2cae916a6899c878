// Colour options, number lists and mesh summaries of the Chapter 2 commands.
#include "visual_options.h"

#include <cmath>
#include <cstdlib>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace isoform::cli {
namespace {

const char* const kMaps[] = {"viridis", "diverging", "green-white"};

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out(1);
  for (char c : text) {
    if (c == ',')
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

}  // namespace

void add_colour_options(CLI::App& app, ColourArgs& args, const std::string& default_map) {
  app.add_option("--map", args.map, "Colour map: viridis, diverging (white at 0) or green-white (default: " +
                                        default_map + ")")
      ->check(CLI::IsMember({"viridis", "diverging", "green-white"}));
  app.add_option("--range", args.range,
                 "Values mapped to the first and last colour, LO,HI (default: the least and greatest "
                 "value sampled; diverging: symmetric about 0)");
  app.add_option("--levels", args.levels, "Colour indices of the map (Section 2.2), 2..65536 (default 256)");
}

void apply_colour_options(const ColourArgs& args, isoform_colour_options& out) {
  for (int m = 0; m < 3; ++m)
    if (args.map == kMaps[m]) out.map = m;
  out.levels = args.levels;
  if (!args.range.empty()) {
    const std::vector<double> r = parse_numbers(args.range, "--range", 2);
    out.fixed_range = 1;
    out.range_min = r[0];
    out.range_max = r[1];
  }
}

std::vector<double> parse_numbers(const std::string& text, const std::string& option, size_t n) {
  const std::vector<std::string> words = split(text);
  if (words.size() != n && !(words.size() == 1 && n > 1 && option != "--range"))
    throw Failure(option + " '" + text + "': expected " + std::to_string(n) + " numbers separated by commas");
  std::vector<double> out;
  for (const std::string& w : words) {
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (w.empty() || *end != '\0' || !std::isfinite(v))
      throw Failure(option + " '" + text + "': '" + w + "' is not a number");
    out.push_back(v);
  }
  out.resize(n, out[0]);
  return out;
}

std::vector<int> parse_integers(const std::string& text, const std::string& option, size_t n) {
  std::vector<int> out;
  for (double v : parse_numbers(text, option, n)) {
    if (v != std::floor(v) || std::fabs(v) > 1e9)
      throw Failure(option + " '" + text + "': expected whole numbers");
    out.push_back(int(v));
  }
  return out;
}

std::string map_name(int map) { return map >= 0 && map < 3 ? kMaps[map] : "unknown"; }

Json coloured_mesh_json(const isoform_mesh* mesh, const std::string& path) {
  const isoform_mesh_stats stats = mesh_stats(mesh);
  return {{"file", path},
          {"vertices", stats.vertices},
          {"triangles", stats.triangles},
          {"edges", (long long)isoform_mesh_edge_count(mesh)},
          {"bbox_min", {stats.bbox_min[0], stats.bbox_min[1], stats.bbox_min[2]}},
          {"bbox_max", {stats.bbox_max[0], stats.bbox_max[1], stats.bbox_max[2]}}};
}

}  // namespace isoform::cli
