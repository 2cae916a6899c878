// The contour step that `contour` and `pipeline` share: options on the
// command line, the checks around isoform_contour, and writing the mesh.
#pragma once

#include <string>

#include <CLI/App.hpp>

#include "cli.h"
#include "progress.h"

namespace isoform::cli {

struct ContourSettings {
  bool auto_isovalue = true;  // false once --iso is given
  double isovalue = 0.0;
  std::string method = "cells";       // cells | tetra
  std::string orientation = "auto";   // auto | increasing | decreasing
  int threads = 0;                    // 0 = all cores
  ProgressOptions progress;
};

// Registers --iso (described by iso_help), --method, --orientation, --threads,
// --progress and --quiet on app, bound to settings.
void add_contour_options(CLI::App& app, ContourSettings& settings, const std::string& iso_help);

struct ContourResult {
  MeshPtr mesh;
  isoform_mesh_stats stats{};
  double seconds = 0.0;  // wall time of isoform_contour
};

// Contours grid `grid` of volume (read from file `input`, named in messages).
// Fails before contouring when a given isovalue lies outside the grid's value
// range, and after it when the mesh is empty; notes on stderr which isovalue
// was chosen when it was automatic for a grid that is not a level set.
ContourResult contour_grid(const std::string& input, const isoform_volume* volume, int grid,
                           const ContourSettings& settings);

// Writes mesh to path (format by extension; atomic in the library) and
// returns the seconds it took.
double save_mesh(const isoform_mesh* mesh, const std::string& path);

}  // namespace isoform::cli
