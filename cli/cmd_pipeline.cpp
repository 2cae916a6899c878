// `isoform pipeline`: the README's main job with no input. It generates the
// built-in head phantom, writes it as a .vdb, reads that file back (so the
// file path is exercised as a user's scan would be), contours it and writes
// the mesh, then the mesh's curvature (Chapter 4) as PLY vertex properties
// and colours. Each step is one small function; later issues add reduction
// and the smooth surface as further steps.
#include <filesystem>
#include <iostream>
#include <memory>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.h"
#include "contouring.h"
#include "curvature_step.h"
#include "paths.h"
#include "report.h"

namespace isoform::cli {
namespace {

// The phantom's skull shell has density 1.0 and its brain 0.2: 0.5 gives the
// skull's outer and inner surfaces.
constexpr double kPhantomIsovalue = 0.5;
// About 128^3 samples: the usual size, contoured in seconds.
constexpr int kPhantomSize = 128;

struct PipelineArgs {
  std::string folder = "isoform-out";
  int size = kPhantomSize;
  ContourSettings settings;
  CurvatureSettings curvature;
  bool json = false;
};

// What the steps wrote, for the summary.
struct PipelineResult {
  std::string volume_path;
  std::string mesh_path;
  std::string curvature_path;
  isoform_mesh_stats stats{};
  double contour_seconds = 0.0;
  double curvature_seconds = 0.0;
  Json curvature;
};

std::string path_in(const std::string& folder, const char* name) {
  return (std::filesystem::path(folder) / name).string();
}

void write_phantom(int size, const std::string& path) {
  isoform_volume* raw = nullptr;
  check(isoform_volume_phantom(size, &raw));
  const VolumePtr phantom(raw);
  check(isoform_volume_save_vdb(phantom.get(), path.c_str()));
}

MeshPtr contour_volume_file(const std::string& volume_path, const ContourSettings& settings,
                            PipelineResult& result) {
  const VolumePtr volume = open_volume(volume_path);
  const int grid = find_grid(volume.get(), "");
  ContourResult contour = contour_grid(volume_path, volume.get(), grid, settings);
  save_mesh(contour.mesh.get(), result.mesh_path);
  result.stats = contour.stats;
  result.contour_seconds = contour.seconds;
  return std::move(contour.mesh);
}

// The contour's curvature from the volume's normals, saved beside it.
void curvature_of(isoform_mesh* mesh, const PipelineArgs& args, PipelineResult& result) {
  result.curvature_seconds = compute_curvature(mesh, args.curvature, args.settings.threads, args.settings.progress);
  result.curvature = curvature_json(mesh);
  save_mesh(mesh, result.curvature_path);
}

void report_pipeline(const PipelineArgs& args, const PipelineResult& result) {
  if (args.json) {
    Json contour = mesh_json(result.stats);
    contour["method"] = args.settings.method;
    contour["contour_seconds"] = result.contour_seconds;
    Json curvature = result.curvature;
    curvature["curvature_seconds"] = result.curvature_seconds;
    print_json({{"phantom_size", args.size},
                {"contour", contour},
                {"curvature", curvature},
                {"written", {result.volume_path, result.mesh_path, result.curvature_path}}});
    return;
  }
  std::cout << "phantom " << args.size << "^3, method " << args.settings.method << '\n';
  print_mesh(std::cout, result.stats);
  print_row(std::cout, "time", format_seconds(result.contour_seconds));
  std::cout << "curvature, " << args.curvature.method << " fit\n";
  print_row(std::cout, "H", "median " + format_number(result.curvature["mean"]["p50"]) + ", 2-98% [" +
                                format_number(result.curvature["mean"]["p2"]) + ", " +
                                format_number(result.curvature["mean"]["p98"]) + "]");
  print_row(std::cout, "time", format_seconds(result.curvature_seconds));
  std::cout << "wrote " << result.volume_path << '\n'
            << "wrote " << result.mesh_path << '\n'
            << "wrote " << result.curvature_path << '\n';
}

void run_pipeline(const PipelineArgs& args) {
  make_output_folder(args.folder);
  PipelineResult result;
  result.volume_path = path_in(args.folder, "phantom.vdb");
  result.mesh_path = path_in(args.folder, "phantom-contour.ply");
  result.curvature_path = path_in(args.folder, "phantom-curvature.ply");
  write_phantom(args.size, result.volume_path);
  const MeshPtr mesh = contour_volume_file(result.volume_path, args.settings, result);
  curvature_of(mesh.get(), args, result);
  report_pipeline(args, result);
}

}  // namespace

Command add_pipeline_command(CLI::App& parent) {
  auto args = std::make_shared<PipelineArgs>();
  args->settings.auto_isovalue = false;
  args->settings.isovalue = kPhantomIsovalue;
  CLI::App* app = parent.add_subcommand(
      "pipeline", "Run the whole job on the built-in head phantom, no input needed");
  app->footer(
      "Writes DIR/phantom.vdb (a Shepp-Logan style head of nested ellipsoids), reads it back, "
      "contours it and writes DIR/phantom-contour.ply, then its principal curvatures "
      "(vertex properties k1 k2 mean gauss absolute, directions, colours by mean curvature) "
      "into DIR/phantom-curvature.ply.");
  app->add_option("-o,--output", args->folder, "Output folder DIR, created if missing")
      ->capture_default_str();
  app->add_option("--size", args->size, "Phantom samples per axis (at least 16)")
      ->capture_default_str();
  add_contour_options(*app, args->settings,
                      "Isovalue (default 0.5: the skull's outer and inner surfaces)");
  add_curvature_options(*app, args->curvature, "--curvature-method");
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args] { run_pipeline(*args); }};
}

}  // namespace isoform::cli
