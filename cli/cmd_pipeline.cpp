// `isoform pipeline [in.vdb]`: the README's main job. With no input it
// generates the built-in head phantom and writes it as a .vdb, which it reads
// back (so the file path is exercised as a user's scan would be). It then
// contours the volume and writes the mesh, the mesh's curvature (Chapter 4)
// as PLY vertex properties and colours, the reduced mesh (Chapter 5, new
// points kept on their fitted surfaces, since the next step interpolates
// them), the side-vertex surface over it (Chapter 6), and the comparison
// with the Loop limit surface against the volume itself (a study folder).
// Blender, when present, renders pictures of them, and a page
// (NAME-report.html) shows the figures and the pictures together.
// Each step is one small function.
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
#include "pipeline_page.h"
#include "reduce_step.h"
#include "study_tools.h"
#include "report.h"
#include "surface_steps.h"

namespace isoform::cli {
namespace {

// The phantom's skull shell has density 1.0 and its brain 0.2: 0.5 gives the
// skull's outer and inner surfaces.
constexpr double kPhantomIsovalue = 0.5;
// About 128^3 samples: the usual size, contoured in seconds.
constexpr int kPhantomSize = 128;

struct PipelineArgs {
  std::string input;  // empty: the phantom
  std::string grid;
  std::string folder = "isoform-out";
  int size = kPhantomSize;
  ContourSettings settings;
  CurvatureSettings curvature;
  std::string keep = "10%";
  int level = 2;          // side-vertex tessellation
  int compare_level = 4;  // comparison lattice
  bool no_render = false;
  bool json = false;
};

// What the steps wrote, for the summary.
struct PipelineResult {
  std::string stem;  // "phantom" or the input's name
  std::string volume_path;
  std::string mesh_path;
  std::string curvature_path;
  std::string reduced_path, smooth_path, study_path, page_path;
  // Picture files relative to the folder, with captions; or why there are none.
  std::vector<std::pair<std::string, std::string>> pictures;
  std::string pictures_note;
  isoform_mesh_stats stats{};
  double contour_seconds = 0.0;
  double curvature_seconds = 0.0;
  double reduce_seconds = 0.0;
  Json curvature, reduce, smooth, study;
};

std::string path_in(const std::string& folder, const std::string& name) {
  return (std::filesystem::path(folder) / name).string();
}

void write_phantom(int size, const std::string& path) {
  isoform_volume* raw = nullptr;
  check(isoform_volume_phantom(size, &raw));
  const VolumePtr phantom(raw);
  check(isoform_volume_save_vdb(phantom.get(), path.c_str()));
}

MeshPtr contour_volume(const std::string& volume_path, const isoform_volume* volume, int grid,
                       const ContourSettings& settings, PipelineResult& result) {
  ContourResult contour = contour_grid(volume_path, volume, grid, settings);
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

// Chapter 5: the reduced mesh, its new points on their fitted surfaces.
void reduce_step(isoform_mesh* mesh, const PipelineArgs& args, PipelineResult& result) {
  ReduceSettings settings;
  settings.keep_fraction = parse_fraction(args.keep, "--keep");
  settings.refine_point = false;
  result.reduce_seconds = reduce_mesh(mesh, settings, result.mesh_path, args.settings.progress);
  result.reduce = reduce_json(mesh, result.reduce_seconds);
  save_mesh(mesh, result.reduced_path);
}

// Chapter 6 over the reduced mesh, then the comparison against the volume.
void surface_steps(const isoform_mesh* reduced, const isoform_volume* volume, int grid,
                   const PipelineArgs& args, PipelineResult& result) {
  const MeshPtr smooth = smooth_surface(reduced, args.level, result.reduced_path, args.settings.progress);
  save_mesh(smooth.get(), result.smooth_path);
  result.smooth = mesh_json(mesh_stats(smooth.get()));
  result.study = compare_study(reduced, volume, grid, result.stats.isovalue, args.compare_level,
                               result.reduced_path, result.study_path, args.settings.progress);
}

// Blender renders the pictures from the files just written, in one run
// (cli/study/render_pipeline.py); without it, or when it fails, the page
// says why and everything else stands.
void make_pictures(const PipelineArgs& args, PipelineResult& result) {
  const std::string blender = args.no_render ? "" : find_program({"blender"});
  const std::string log = path_in(args.folder, result.stem + "-pictures.log");
  if (args.no_render) {
    result.pictures_note = "No pictures: --no-render.";
  } else if (blender.empty()) {
    result.pictures_note = "No pictures: Blender was not found (apt-get install blender).";
  } else {
    const int code = run_program({blender, "-b", "--factory-startup", "--python-exit-code", "1", "--python",
                                  study_scripts_folder() + "/render_pipeline.py", "--", args.folder, result.stem},
                                 log);
    if (code != 0)
      result.pictures_note = "No pictures: Blender exited with " + std::to_string(code) + " (see " + result.stem +
                             "-pictures.log).";
  }
  if (!result.pictures_note.empty()) {
    if (!args.settings.progress.quiet) std::cerr << "isoform: note: " << result.pictures_note << '\n';
    return;
  }
  std::filesystem::remove(log);
  const std::string& s = result.stem;
  result.pictures = {{s + "-curvature.png", "The contour coloured by its mean curvature (blue below zero, red above)"},
                     {s + "-reduced.png", "The reduced mesh (Chapter 5), its triangles drawn"},
                     {s + "-smooth.png", "The side-vertex surface over the reduced mesh (Chapter 6)"}};
  for (auto& [name, measures] : result.study.items())
    for (const char* kind : {"isophotes", "reflection"})
      result.pictures.push_back({s + "-study/render-" + name + "-" + kind + ".png",
                                 "Comparison: " + name + ", " + (kind[0] == 'i' ? "isophotes" : "reflection lines")});
}

std::string relative_to(const std::string& folder, const std::string& path) {
  return std::filesystem::path(path).lexically_relative(folder).string();
}

void write_page(const PipelineArgs& args, const PipelineResult& result) {
  PipelinePage page;
  page.title = args.input.empty() ? "phantom " + std::to_string(args.size) + "^3" : args.input;
  page.rows = {
      {"contour (Chapter 3)", std::to_string(result.stats.triangles) + " triangles, " +
                                  std::to_string(result.stats.parts) + " parts, isovalue " +
                                  format_number(result.stats.isovalue) + ", " + format_seconds(result.contour_seconds)},
      {"mean curvature (Chapter 4)", "median " + format_number(result.curvature["mean"]["p50"]) + ", 2-98 % [" +
                                         format_number(result.curvature["mean"]["p2"]) + ", " +
                                         format_number(result.curvature["mean"]["p98"]) + "]"},
      {"reduction (Chapter 5)", std::to_string(result.reduce["triangles_after"].get<long long>()) +
                                    " triangles (" + args.keep + " asked), " + format_seconds(result.reduce_seconds)},
      {"side-vertex surface (Chapter 6)", "level " + std::to_string(args.level) + ", " +
                                              std::to_string(result.smooth["triangles"].get<long long>()) + " triangles"}};
  for (auto& [name, m] : result.study.items())
    page.rows.push_back({"against the volume: " + name,
                         "deviation RMS " + format_number(m["deviation_voxels"]["rms"].get<double>()) +
                             " voxels, normal gap max " + format_number(m["normal_gap"]["max"].get<double>()) + " rad"});
  page.pictures = result.pictures;
  page.pictures_note = result.pictures_note;
  for (const std::string& path : {result.mesh_path, result.curvature_path, result.reduced_path, result.smooth_path,
                                  result.study_path + "/report.md"})
    page.files.push_back(relative_to(args.folder, path));
  write_pipeline_page(result.page_path, page);
}

std::vector<std::string> written(const PipelineResult& r) {
  std::vector<std::string> files = {r.mesh_path, r.curvature_path, r.reduced_path, r.smooth_path,
                                    r.study_path + "/report.md"};
  if (r.stem == "phantom") files.insert(files.begin(), r.volume_path);
  files.push_back(r.page_path);
  return files;
}

void report_pipeline(const PipelineArgs& args, const PipelineResult& result) {
  if (args.json) {
    Json contour = mesh_json(result.stats);
    contour["method"] = args.settings.method;
    contour["contour_seconds"] = result.contour_seconds;
    Json curvature = result.curvature;
    curvature["curvature_seconds"] = result.curvature_seconds;
    print_json({{"input", args.input.empty() ? "phantom" : args.input},
                {"phantom_size", args.input.empty() ? args.size : 0},
                {"contour", contour},
                {"curvature", curvature},
                {"reduce", result.reduce},
                {"smooth", result.smooth},
                {"compare", result.study},
                {"pictures", result.pictures_note.empty() ? std::string("made") : result.pictures_note},
                {"written", written(result)}});
    return;
  }
  if (args.input.empty()) std::cout << "phantom " << args.size << "^3, method " << args.settings.method << '\n';
  else std::cout << args.input << ", method " << args.settings.method << '\n';
  print_mesh(std::cout, result.stats);
  print_row(std::cout, "time", format_seconds(result.contour_seconds));
  std::cout << "curvature, " << args.curvature.method << " fit\n";
  print_row(std::cout, "H", "median " + format_number(result.curvature["mean"]["p50"]) + ", 2-98% [" +
                                format_number(result.curvature["mean"]["p2"]) + ", " +
                                format_number(result.curvature["mean"]["p98"]) + "]");
  print_row(std::cout, "time", format_seconds(result.curvature_seconds));
  std::cout << "reduction to " << args.keep << '\n';
  print_row(std::cout, "triangles", std::to_string(result.reduce["triangles_after"].get<long long>()));
  print_row(std::cout, "time", format_seconds(result.reduce_seconds));
  std::cout << "side-vertex surface, level " << args.level << '\n';
  print_row(std::cout, "triangles", std::to_string(result.smooth["triangles"].get<long long>()));
  std::cout << "comparison against the volume (deviation in voxels, RMS)\n";
  for (auto& [name, s] : result.study.items())
    print_row(std::cout, name, format_number(s["deviation_voxels"]["rms"].get<double>()) + ", normal gap max " +
                                   format_number(s["normal_gap"]["max"].get<double>()) + " rad");
  for (const std::string& path : written(result)) std::cout << "wrote " << path << '\n';
}

std::string stem_of(const std::string& input) {
  return input.empty() ? "phantom" : std::filesystem::path(input).stem().string();
}

void run_pipeline(PipelineArgs args) {
  make_output_folder(args.folder);
  PipelineResult result;
  result.stem = stem_of(args.input);
  result.volume_path = args.input.empty() ? path_in(args.folder, "phantom.vdb") : args.input;
  result.mesh_path = path_in(args.folder, result.stem + "-contour.ply");
  result.curvature_path = path_in(args.folder, result.stem + "-curvature.ply");
  result.reduced_path = path_in(args.folder, result.stem + "-reduced.ply");
  result.smooth_path = path_in(args.folder, result.stem + "-smooth.ply");
  result.study_path = path_in(args.folder, result.stem + "-study");
  result.page_path = path_in(args.folder, result.stem + "-report.html");
  if (args.input.empty()) {
    write_phantom(args.size, result.volume_path);
    if (args.settings.auto_isovalue) {  // no --iso: the skull's surfaces
      args.settings.auto_isovalue = false;
      args.settings.isovalue = kPhantomIsovalue;
    }
  }
  const VolumePtr volume = open_volume(result.volume_path);
  const int grid = find_grid(volume.get(), args.grid);
  const MeshPtr mesh = contour_volume(result.volume_path, volume.get(), grid, args.settings, result);
  curvature_of(mesh.get(), args, result);
  reduce_step(mesh.get(), args, result);
  surface_steps(mesh.get(), volume.get(), grid, args, result);
  make_pictures(args, result);
  write_page(args, result);
  report_pipeline(args, result);
}

}  // namespace

Command add_pipeline_command(CLI::App& parent) {
  auto args = std::make_shared<PipelineArgs>();
  CLI::App* app = parent.add_subcommand(
      "pipeline", "Run the whole job: contour, curvature, reduction, smooth surface, comparison");
  app->footer(
      "With no input, writes DIR/phantom.vdb (a Shepp-Logan style head of nested ellipsoids) and "
      "reads it back. Then writes DIR/NAME-contour.ply (Chapter 3), DIR/NAME-curvature.ply "
      "(vertex properties k1 k2 mean gauss absolute, directions, colours by mean curvature; "
      "Chapter 4), DIR/NAME-reduced.ply (Chapter 5, --keep of the triangles, new points on "
      "their fitted surfaces), DIR/NAME-smooth.ply (the side-vertex surface over it, Chapter 6) "
      "and DIR/NAME-study/ (the flat triangles, the Loop limit surface and the side-vertex "
      "surface measured against the volume: report.md, report.json, samples.csv, one PLY per "
      "surface), then, with Blender, pictures of each (NAME-curvature.png, NAME-reduced.png, "
      "NAME-smooth.png, the study's isophotes and reflection lines) and DIR/NAME-report.html, "
      "the page that shows them. NAME is phantom or the input's name.");
  app->add_option("file", args->input, "Volume file (.vdb); default: the built-in phantom");
  app->add_option("--grid", args->grid, "Grid to contour; default: the first scalar grid");
  app->add_option("-o,--output", args->folder, "Output folder DIR, created if missing")
      ->capture_default_str();
  app->add_option("--size", args->size, "Phantom samples per axis (at least 16)")
      ->capture_default_str();
  add_contour_options(*app, args->settings,
                      "Isovalue (phantom: 0.5, the skull's outer and inner surfaces; a file: 0 for a "
                      "level set, else the middle of the value range)");
  add_curvature_options(*app, args->curvature, "--curvature-method");
  app->add_option("--keep", args->keep, "Triangles the reduction keeps: a percentage or a fraction")
      ->capture_default_str();
  app->add_option("--level", args->level, "Side-vertex tessellation level: 4^level triangles each")
      ->check(CLI::Range(0, 6))
      ->capture_default_str();
  app->add_option("--compare-level", args->compare_level, "Comparison lattice level k per triangle")
      ->check(CLI::Range(1, 32))
      ->capture_default_str();
  app->add_flag("--no-render", args->no_render, "Skip the Blender pictures");
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args] { run_pipeline(*args); }};
}

}  // namespace isoform::cli
