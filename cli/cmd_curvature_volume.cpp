// `isoform curvature-volume FILE -o OUT.vdb`: the principal curvatures of the
// graph of one grid (Hamann 1991, Section 4.3) as five grids of a new VDB.
#include <chrono>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.h"
#include "paths.h"
#include "report.h"

namespace isoform::cli {
namespace {

const char* const kResultGrids[5] = {"mean", "gauss", "k1", "k2", "k3"};

struct CurvatureVolumeArgs {
  std::string input;
  std::string output;
  std::string grid;              // "" = the first scalar grid
  std::string method = "default";
  bool json = false;
};

Json summary_json(const isoform_curvature_summary& s) {
  return {{"min", s.min}, {"max", s.max}, {"mean", s.mean}, {"p01", s.p01}, {"p05", s.p05}, {"p25", s.p25},
          {"p50", s.p50}, {"p75", s.p75}, {"p95", s.p95}, {"p99", s.p99}};
}

Json fits_json(const isoform_volume_curvature_stats& stats) {
  Json fits = Json::array();
  for (int f = 0; f < ISOFORM_GRAPH_FIT_COUNT; ++f)
    fits.push_back({{"fit", f}, {"what", isoform_graph_fit_name(f)}, {"points", stats.fits[f]}});
  return fits;
}

void report(const CurvatureVolumeArgs& args, const isoform_grid_info& info,
            const isoform_volume_curvature_stats& stats, double seconds) {
  if (args.json) {
    Json grids = Json::object();
    for (int g = 0; g < 5; ++g) grids[kResultGrids[g]] = summary_json(stats.grids[g]);
    print_json({{"input", args.input}, {"grid", std::string(info.name)}, {"method", args.method},
                {"output", args.output}, {"points", stats.points}, {"fits", fits_json(stats)},
                {"grids", grids}, {"seconds", seconds}});
    return;
  }
  std::cout << args.input << ", grid '" << info.name << "', method " << args.method << '\n';
  print_row(std::cout, "points", std::to_string(stats.points));
  for (int g = 0; g < 5; ++g) {
    const isoform_curvature_summary& s = stats.grids[g];
    print_row(std::cout, kResultGrids[g],
              "min " + format_number(s.min) + "  p05 " + format_number(s.p05) + "  p50 " +
                  format_number(s.p50) + "  mean " + format_number(s.mean) + "  p95 " +
                  format_number(s.p95) + "  max " + format_number(s.max));
  }
  for (int f = 0; f < ISOFORM_GRAPH_FIT_COUNT; ++f)
    if (stats.fits[f] > 0 && f != ISOFORM_GRAPH_FIT_JET_CENTRED && f != ISOFORM_GRAPH_FIT_PLATELET)
      print_row(std::cout, "fallback", std::to_string(stats.fits[f]) + " points: " + isoform_graph_fit_name(f));
  print_row(std::cout, "time", format_seconds(seconds));
  std::cout << "wrote " << args.output << '\n';
}

void run_curvature_volume(const CurvatureVolumeArgs& args) {
  check_output_path(args.input, args.output, {".vdb"});
  const VolumePtr volume = open_volume(args.input);
  const int grid = find_grid(volume.get(), args.grid);
  const isoform_grid_info info = grid_info(volume.get(), grid);
  if (!info.is_scalar)
    throw Failure(args.input + ": grid '" + info.name + "' is a " + info.value_type +
                  " grid; curvature needs a scalar grid");
  isoform_volume_curvature_options options;
  isoform_volume_curvature_options_default(&options);
  options.method = args.method == "seed" ? ISOFORM_VOLUME_CURVATURE_SEED : ISOFORM_VOLUME_CURVATURE_DEFAULT;
  const auto start = std::chrono::steady_clock::now();
  isoform_volume* raw = nullptr;
  check(isoform_volume_curvature(volume.get(), grid, &options, nullptr, &raw));
  const VolumePtr result(raw);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  isoform_volume_curvature_stats stats;
  check(isoform_volume_curvature_stats_get(result.get(), &stats));
  check(isoform_volume_save_vdb(result.get(), args.output.c_str()));
  report(args, info, stats, seconds);
}

}  // namespace

Command add_curvature_volume_command(CLI::App& parent) {
  auto args = std::make_shared<CurvatureVolumeArgs>();
  CLI::App* app = parent.add_subcommand(
      "curvature-volume",
      "Principal curvatures of the graph of a grid (a hypersurface in 4-D) as a new .vdb");
  app->footer(
      "Writes five float grids, mean (H), gauss (K), k1 >= k2 >= k3, with the input grid's "
      "transform, active exactly at its active voxels (Hamann 1991, Section 4.3). The default "
      "method fits a degree-6 polynomial to f on a 7x7x7 box of active voxels (moved inward at "
      "the data's edge); --method seed uses the seed's 14-point platelet fit. The summary counts "
      "the points that needed a fallback fit. Example: isoform curvature-volume smoke.vdb -o curv.vdb");
  app->add_option("file", args->input, "Volume file (.vdb, .nrrd, .nhdr, .nii, .nii.gz)")->required();
  app->add_option("-o,--output", args->output, "OpenVDB file to write (.vdb); never the input")->required();
  app->add_option("--grid", args->grid, "Grid to use (default: the first scalar grid)");
  app->add_option("--method", args->method, "default or seed (default: default)")
      ->check(CLI::IsMember({"default", "seed"}));
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args] { run_curvature_volume(*args); }};
}

}  // namespace isoform::cli
