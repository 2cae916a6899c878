// `isoform contour FILE -o OUT`: one grid to a closed triangle mesh file.
#include <cctype>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.h"
#include "contouring.h"
#include "curvature_step.h"
#include "part_step.h"
#include "paths.h"
#include "reduce_step.h"
#include "report.h"

namespace isoform::cli {
namespace {

struct ContourArgs {
  std::string input;
  std::string output;
  std::string grid;  // "" = the first scalar grid
  ContourSettings settings;
  bool curvature = false;
  CurvatureSettings curvature_settings;
  std::string reduce;  // the share to remove (90% or 0.9), when reduce_given
  bool reduce_given = false;
  double reduce_seconds = 0.0;
  PartSettings parts;
  isoform_part_filter_stats dropped{};
  std::string space;       // --space: the patient frame to write in ("" = the input's)
  std::string from_space;  // the input's frame, when --space converted it
  bool json = false;
};

// --space: the mesh moved from the grid's stated frame into the one asked
// (RAS, LPS, LAS differ only in the signs of x and y).
void convert_space(ContourArgs& args, isoform_mesh* mesh, const isoform_grid_info& info) {
  if (args.space.empty()) return;
  const std::string from = info.space;
  if (from.empty())
    throw Failure(args.input + ": does not state its patient frame, so --space " + args.space +
                      " cannot convert it",
                  2);
  if (from == args.space) return;
  const double matrix[16] = {from[0] == args.space[0] ? 1.0 : -1.0, 0, 0, 0,
                             0, from[1] == args.space[1] ? 1.0 : -1.0, 0, 0,
                             0, 0, 1, 0,
                             0, 0, 0, 1};
  check(isoform_mesh_transform(mesh, matrix));
  args.from_space = from;
}

void report_contour(const ContourArgs& args, const isoform_grid_info& info,
                    const ContourResult& result, double write_seconds) {
  if (args.json) {
    Json j = {{"input", args.input},
                        {"grid", std::string(info.name)},
                        {"class", class_name(info.grid_class)},
                        {"method", args.settings.method},
                        {"output", args.output},
                        {"space", info.space[0] ? Json(std::string(info.space)) : Json()},
                        {"unit", info.unit[0] ? Json(std::string(info.unit)) : Json()},
                        {"contour_seconds", result.seconds},
                        {"write_seconds", write_seconds}};
    j.update(mesh_json(result.stats));
    if (!args.from_space.empty()) {
      j["space"] = args.space;
      j["space_converted_from"] = args.from_space;
    }
    if (args.parts.wanted()) j.update(parts_json(args.dropped));
    if (args.curvature) j["curvature"] = curvature_json(result.mesh.get());
    if (args.reduce_given) j["reduce"] = reduce_json(result.mesh.get(), args.reduce_seconds);
    print_json(j);
    return;
  }
  std::cout << args.input << ", grid '" << info.name << "' (" << class_name(info.grid_class)
            << "), method " << args.settings.method << '\n';
  print_row(std::cout, "world frame",
            args.from_space.empty() ? frame_text(info)
                                    : args.space + " (converted from " + args.from_space + "), unit " +
                                          (info.unit[0] ? std::string(info.unit) : "not stated"));
  print_mesh(std::cout, result.stats);
  if (args.parts.wanted()) print_parts(std::cout, args.dropped);
  if (args.curvature) print_curvature(std::cout, result.mesh.get());
  if (args.reduce_given) print_reduce(std::cout, result.mesh.get(), args.reduce_seconds);
  print_row(std::cout, "time", format_seconds(result.seconds));
  std::cout << "wrote " << args.output << '\n';
}

// The share --reduce removes, in [0, 1) (0: the checks, then a copy).
double removed_share(const std::string& text) {
  const double removed = parse_share(text, "--reduce");
  if (removed >= 1.0) throw Failure("--reduce: '" + text + "' would remove every triangle (write less than 100%)");
  if (!(removed >= 0)) throw Failure("--reduce: '" + text + "' must lie in [0, 1), that is [0%, 100%)");
  return removed;
}

// --reduce R removes the share R of the contour's triangles (Chapter 5).
void reduce_contour(ContourArgs& args, isoform_mesh* mesh) {
  if (!args.reduce_given) return;
  const double removed = removed_share(args.reduce);
  ReduceSettings settings;
  settings.keep_fraction = 1.0 - removed;
  args.reduce_seconds = reduce_mesh(mesh, settings, args.input, args.settings.progress);
}

void run_contour(ContourArgs& args) {
  if (args.reduce_given) removed_share(args.reduce);  // fail before the contour
  if (args.curvature)
    check_output_path(args.input, args.output, {".ply"});  // only PLY carries curvature
  else
    check_output_path(args.input, args.output, {".ply", ".obj", ".stl"});
  const VolumePtr volume = open_volume(args.input);
  const int grid = find_grid(volume.get(), args.grid);
  const isoform_grid_info info = grid_info(volume.get(), grid);
  const isoform_part_filter filter = part_filter(args.parts, info.unit, args.input);  // fail before the contour
  ContourResult result = contour_grid(args.input, volume.get(), grid, args.settings);
  if (args.parts.wanted()) args.dropped = drop_parts(result.mesh.get(), filter);
  convert_space(args, result.mesh.get(), info);
  if (args.parts.wanted() || !args.from_space.empty()) result.stats = mesh_stats(result.mesh.get());
  if (args.curvature)
    compute_curvature(result.mesh.get(), args.curvature_settings, args.settings.threads, args.settings.progress);
  reduce_contour(args, result.mesh.get());
  if (args.reduce_given) result.stats = mesh_stats(result.mesh.get());
  const double write_seconds = save_mesh(result.mesh.get(), args.output);
  report_contour(args, info, result, write_seconds);
}

}  // namespace

Command add_contour_command(CLI::App& parent) {
  auto args = std::make_shared<ContourArgs>();
  CLI::App* app = parent.add_subcommand(
      "contour", "Contour a grid into a closed triangle mesh (.ply, .obj, .stl)");
  app->footer(
      "The mesh is closed, manifold and consistently oriented, in world coordinates, with a "
      "unit normal per vertex (PLY and OBJ) and a part id per triangle (PLY). Without --iso, a "
      "grid that is not a level set is contoured at the midpoint of its value range, and a note "
      "on stderr says so. Example: isoform contour scan.vdb --iso 500 -o skin.ply");
  app->add_option("file", args->input, "Volume file (.vdb, .nrrd, .nhdr, .nii, .nii.gz)")->required();
  app->add_option("-o,--output", args->output, "Mesh file to write: .ply, .obj or .stl")
      ->required();
  app->add_option("--grid", args->grid, "Grid to contour (default: the first scalar grid)");
  add_contour_options(*app, args->settings,
                      "Isovalue, in the grid's value units (default: 0 for a level set, the "
                      "midpoint of the value range for other grids)");
  app->add_flag("--curvature", args->curvature,
                "Also compute principal curvatures (as `isoform curvature`) from the volume's normals; "
                "needs a .ply output");
  add_curvature_options(*app, args->curvature_settings, "--curvature-method");
  CLI::Option* reduce = app->add_option(
      "--reduce", args->reduce,
      "Then remove this share of the triangles (Chapter 5, as `isoform reduce`): 90% or 0.9; 0% only checks "
      "the mesh as the reduction would");
  add_part_options(*app, args->parts);
  app->add_option("--space", args->space,
                  "Write the mesh in this patient frame: RAS (NIfTI's), LPS (DICOM's) or LAS; the input "
                  "must state its own (default: the input's frame, unchanged)")
      ->transform([](std::string s) {
        for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
        return s;
      })
      ->check(CLI::IsMember({"RAS", "LPS", "LAS"}));
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args, reduce] {
            args->reduce_given = reduce->count() > 0;
            run_contour(*args);
          }};
}

}  // namespace isoform::cli
