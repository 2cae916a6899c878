// --min-part and --largest (see part_step.h).
#include "part_step.h"

#include <cmath>
#include <cstdlib>
#include <map>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace isoform::cli {

namespace {

// Cubic metres per volume unit the option takes.
const std::map<std::string, double>& volume_units() {
  static const std::map<std::string, double> units = {
      {"um3", 1e-18}, {"mm3", 1e-9}, {"cm3", 1e-6}, {"ml", 1e-6}, {"m3", 1.0}};
  return units;
}

// Metres per world unit, for a unit a file states.
double metres(const std::string& unit) {
  return unit == "mm" ? 1e-3 : unit == "um" ? 1e-6 : unit == "m" ? 1.0 : 0.0;
}

[[noreturn]] void bad(const std::string& text) {
  throw Failure("--min-part: '" + text + "' is not a triangle count (50) or a volume (1mm3, 0.5ml, 1cm3, 2u3)", 2);
}

}  // namespace

void add_part_options(CLI::App& app, PartSettings& settings) {
  app.add_option("--min-part", settings.min_part,
                 "Drop parts of fewer triangles (50), or closed parts enclosing less than a volume: 1mm3, "
                 "0.5ml, 1cm3, um3, m3 (the input must state its unit), or u3 (world units cubed)");
  app.add_option("--largest", settings.largest, "Keep only the K parts of most triangles")
      ->check(CLI::PositiveNumber);
}

isoform_part_filter part_filter(const PartSettings& settings, const std::string& unit, const std::string& input) {
  isoform_part_filter filter;
  isoform_part_filter_default(&filter);
  filter.largest = settings.largest;
  const std::string& text = settings.min_part;
  if (text.empty()) return filter;
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  const std::string suffix(end);
  if (end == text.c_str() || !std::isfinite(number) || number < 0) bad(text);
  if (suffix.empty()) {
    if (number != std::floor(number) || number > 1e15) bad(text);
    filter.min_triangles = (long long)number;
    return filter;
  }
  if (suffix == "u3") {
    filter.min_volume = number;
    return filter;
  }
  const auto u = volume_units().find(suffix);
  if (u == volume_units().end()) bad(text);
  if (metres(unit) == 0.0)
    throw Failure(input + ": does not state its unit, so --min-part " + text +
                      " cannot be measured; give the volume in world units cubed (such as 2u3) or a triangle count",
                  2);
  filter.min_volume = number * u->second / std::pow(metres(unit), 3);
  return filter;
}

isoform_part_filter_stats drop_parts(isoform_mesh* mesh, const isoform_part_filter& filter) {
  isoform_part_filter_stats stats{};
  check(isoform_mesh_filter_parts(mesh, &filter, &stats));
  return stats;
}

Json parts_json(const isoform_part_filter_stats& stats) {
  return {{"parts_dropped", stats.parts_before - stats.parts_after},
          {"triangles_dropped", stats.triangles_before - stats.triangles_after}};
}

void print_parts(std::ostream& out, const isoform_part_filter_stats& stats) {
  print_row(out, "parts dropped",
            std::to_string(stats.parts_before - stats.parts_after) + " of " + std::to_string(stats.parts_before) +
                ", with " + std::to_string(stats.triangles_before - stats.triangles_after) + " of " +
                std::to_string(stats.triangles_before) + " triangles");
}

}  // namespace isoform::cli
