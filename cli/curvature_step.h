// The curvature step that `curvature` and `contour --curvature` share: its
// options on the command line, the call with a progress bar, and the summary
// (per quantity: min, max, mean, percentiles; the fallback counts).
#pragma once

#include <ostream>
#include <string>

#include <CLI/App.hpp>

#include "cli.h"
#include "progress.h"
#include "report.h"

namespace isoform::cli {

struct CurvatureSettings {
  std::string method = "quartic";   // seed | quadric | cubic | quartic
  int extra_rings = 0;
  std::string color_by = "mean";    // k1 | k2 | mean | gauss | absolute
  bool update_normals = false;
};

// Registers --method (named method_flag, since `contour` has its own
// --method), --rings, --color-by and --fit-normals on app.
void add_curvature_options(CLI::App& app, CurvatureSettings& settings, const std::string& method_flag);

// Runs isoform_curvature on mesh and returns the seconds it took.
double compute_curvature(isoform_mesh* mesh, const CurvatureSettings& settings, int threads,
                         const ProgressOptions& progress);

// The summary of a mesh's curvature, for --json and for people.
Json curvature_json(const isoform_mesh* mesh);
void print_curvature(std::ostream& out, const isoform_mesh* mesh);

}  // namespace isoform::cli
