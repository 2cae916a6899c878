// The contour step shared by `contour` and `pipeline`.
#include "contouring.h"

#include <chrono>
#include <iostream>

#include <CLI/CLI.hpp>

#include "progress.h"
#include "report.h"

namespace isoform::cli {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

isoform_contour_options library_options(const ContourSettings& settings) {
  isoform_contour_options options;
  isoform_contour_options_default(&options);
  options.auto_isovalue = settings.auto_isovalue ? 1 : 0;
  options.isovalue = settings.isovalue;
  options.method = settings.method == "tetra" ? ISOFORM_METHOD_TETRA : ISOFORM_METHOD_CELLS;
  if (settings.orientation == "increasing") options.orientation = ISOFORM_ORIENT_INCREASING;
  if (settings.orientation == "decreasing") options.orientation = ISOFORM_ORIENT_DECREASING;
  options.threads = settings.threads;
  return options;
}

std::string range_text(const isoform_grid_info& info) {
  return "[" + format_number(info.value_min) + ", " + format_number(info.value_max) + "]";
}

// The library returns an empty mesh for an isovalue outside the range; the
// CLI refuses it up front, so the user does not wait for nothing.
void check_isovalue_in_range(const std::string& input, const isoform_grid_info& info,
                             const ContourSettings& settings) {
  if (settings.auto_isovalue || !info.is_scalar) return;
  if (settings.isovalue >= info.value_min && settings.isovalue <= info.value_max) return;
  throw Failure(input + ": isovalue " + format_number(settings.isovalue) +
                " is outside the value range " + range_text(info) + " of grid '" + info.name +
                "'; the contour is empty");
}

void note_automatic_isovalue(const isoform_grid_info& info, const isoform_mesh_stats& stats,
                             const ContourSettings& settings) {
  if (!stats.isovalue_was_auto || info.grid_class == ISOFORM_CLASS_LEVEL_SET) return;
  if (settings.progress.quiet) return;
  std::cerr << "isoform: grid '" << info.name << "' is not a level set; contoured at isovalue "
            << format_number(stats.isovalue) << ", the midpoint of its value range "
            << range_text(info) << "; --iso sets another\n";
}

}  // namespace

void add_contour_options(CLI::App& app, ContourSettings& settings, const std::string& iso_help) {
  app.add_option_function<double>(
      "--iso",
      [&settings](const double& value) {
        settings.isovalue = value;
        settings.auto_isovalue = false;
      },
      iso_help);
  app.add_option("--method", settings.method,
                 "cells: trilinear-consistent cells (Hamann 1991, Section 3.2); "
                 "tetra: six tetrahedra per cell")
      ->check(CLI::IsMember({"cells", "tetra"}))
      ->capture_default_str();
  app.add_option("--orientation", settings.orientation,
                 "Side the normals face: auto (level set: increasing values, other grids: "
                 "decreasing), increasing, decreasing")
      ->check(CLI::IsMember({"auto", "increasing", "decreasing"}))
      ->capture_default_str();
  app.add_option("--threads", settings.threads, "Worker threads; 0 = all cores, 1 = serial")
      ->check(non_negative_number())
      ->capture_default_str();
  add_progress_flags(app, settings.progress);
}

ContourResult contour_grid(const std::string& input, const isoform_volume* volume, int grid,
                           const ContourSettings& settings) {
  const isoform_grid_info info = grid_info(volume, grid);
  check_isovalue_in_range(input, info, settings);
  const isoform_contour_options options = library_options(settings);
  isoform_mesh* mesh = nullptr;
  const Clock::time_point start = Clock::now();
  run_with_progress(
      [&](isoform_progress* progress) {
        return isoform_contour(volume, grid, &options, progress, &mesh);
      },
      settings.progress);
  ContourResult result;
  result.mesh.reset(mesh);
  result.seconds = seconds_since(start);
  result.stats = mesh_stats(result.mesh.get());
  note_automatic_isovalue(info, result.stats, settings);
  if (result.stats.triangles == 0)
    throw Failure(input + ": the contour of grid '" + info.name + "' at isovalue " +
                  format_number(result.stats.isovalue) + " is empty (value range " +
                  range_text(info) + ")");
  return result;
}

// NOTE: on the progress worker, so that Ctrl-C while a large file is
// written stops the write and removes its temporary file instead of ending
// the process with the temporary file left beside the output.
double save_mesh(const isoform_mesh* mesh, const std::string& path) {
  const Clock::time_point start = Clock::now();
  ProgressOptions quiet;
  quiet.quiet = true;
  run_with_progress([&](isoform_progress* p) { return isoform_mesh_save_progress(mesh, path.c_str(), p); }, quiet);
  return seconds_since(start);
}

}  // namespace isoform::cli
