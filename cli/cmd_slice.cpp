// `isoform slice FILE -o DIR`: the three orthogonal slices of Section 2.3 as
// PNG images with a colour bar, and as meshes (coloured planes, graphs as
// surfaces and as curve networks).
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.h"
#include "paths.h"
#include "report.h"
#include "visual_options.h"

namespace isoform::cli {
namespace {

struct SliceArgs {
  std::string input;
  std::string output;
  std::string grid;
  std::string at;     // "x=0.3,y=0.5,z=0.7", "0.3,0.5,0.7", or "" (the middle)
  bool world = false;
  int resolution = 256;
  double height = 0.25;
  bool no_bar = false;
  ColourArgs colour;
  bool json = false;
};

struct ImageDeleter {
  void operator()(isoform_image* image) const { isoform_image_free(image); }
};
using ImagePtr = std::unique_ptr<isoform_image, ImageDeleter>;

const char* const kAxisNames[] = {"x", "y", "z"};

// The world position of the grid's index point p.
std::array<double, 3> to_world(const isoform_grid_info& info, const std::array<double, 3>& p) {
  std::array<double, 3> w;
  for (int r = 0; r < 3; ++r)
    w[r] = info.transform[4 * r] * p[0] + info.transform[4 * r + 1] * p[1] + info.transform[4 * r + 2] * p[2] +
           info.transform[4 * r + 3];
  return w;
}

// Fills options.position from --at: named or positional, the middle of the
// domain (normalised 0.5, or its world centre) where an axis is not given.
void parse_at(const SliceArgs& args, const isoform_grid_info& info, isoform_slice_options& options) {
  std::array<double, 3> centre;
  for (int a = 0; a < 3; ++a) centre[a] = 0.5 * (info.bbox_min[a] + info.bbox_max[a]);
  const std::array<double, 3> world_centre = to_world(info, centre);
  for (int a = 0; a < 3; ++a) options.position[a] = args.world ? world_centre[a] : 0.5;
  if (args.at.empty()) return;
  std::string word;
  int next = 0;
  auto take = [&](const std::string& w) {
    int axis = next;
    std::string number = w;
    if (w.size() > 2 && w[1] == '=') {
      axis = w[0] == 'x' ? 0 : w[0] == 'y' ? 1 : w[0] == 'z' ? 2 : -1;
      number = w.substr(2);
    }
    if (axis < 0 || axis > 2) throw Failure("--at '" + args.at + "': '" + w + "' is not x=, y= or z= a number");
    char* end = nullptr;
    options.position[axis] = std::strtod(number.c_str(), &end);
    if (number.empty() || *end != '\0' || !std::isfinite(options.position[axis]))
      throw Failure("--at '" + args.at + "': '" + w + "' is not x=, y= or z= a number");
    next = axis + 1;
  };
  for (char c : args.at + ",") {
    if (c != ',') {
      word += c;
      continue;
    }
    take(word);
    word.clear();
  }
}

void run_slice(const SliceArgs& args) {
  const VolumePtr volume = open_volume(args.input);
  const int grid = find_grid(volume.get(), args.grid);
  const isoform_grid_info info = grid_info(volume.get(), grid);
  isoform_slice_options options;
  isoform_slice_options_default(&options);
  parse_at(args, info, options);
  options.world = args.world;
  options.resolution = args.resolution;
  options.height = args.height;
  options.colour_bar = !args.no_bar;
  apply_colour_options(args.colour, options.colour);
  // Everything is made before anything is written: a bad position or grid
  // leaves no file behind.
  std::vector<ImagePtr> images;
  for (int axis = 0; axis < 3; ++axis) {
    isoform_image* image = nullptr;
    check(isoform_slice_image(volume.get(), grid, axis, &options, &image));
    images.emplace_back(image);
  }
  const char* const kinds[] = {"planes", "surfaces", "curves"};
  std::vector<MeshPtr> meshes;
  for (int kind = 0; kind < 3; ++kind) {
    isoform_mesh* mesh = nullptr;
    check(isoform_slice_mesh(volume.get(), grid, 3, kind, &options, &mesh));
    meshes.emplace_back(mesh);
  }
  make_output_folder(args.output);
  Json written = Json::array(), image_list = Json::array(), mesh_list = Json::array();
  for (int axis = 0; axis < 3; ++axis) {
    const std::string path = args.output + "/slice-" + kAxisNames[axis] + ".png";
    check(isoform_image_save_png(images[axis].get(), path.c_str()));
    image_list.push_back({{"file", path}, {"axis", kAxisNames[axis]},
                          {"width", isoform_image_width(images[axis].get())},
                          {"height", isoform_image_height(images[axis].get())}});
    written.push_back(path);
  }
  for (int kind = 0; kind < 3; ++kind) {
    const std::string path = args.output + "/slice-" + kinds[kind] + ".ply";
    check(isoform_mesh_save(meshes[kind].get(), path.c_str()));
    Json m = coloured_mesh_json(meshes[kind].get(), path);
    m["kind"] = kinds[kind];
    mesh_list.push_back(m);
    written.push_back(path);
  }
  double f_min = 0, f_max = 0;
  check(isoform_image_range(images[0].get(), &f_min, &f_max));
  if (args.json) {
    print_json({{"input", args.input}, {"grid", std::string(info.name)}, {"class", class_name(info.grid_class)},
                {"position", {options.position[0], options.position[1], options.position[2]}},
                {"position_is_world", args.world}, {"resolution", args.resolution},
                {"map", map_name(options.colour.map)}, {"range", {f_min, f_max}},
                {"images", image_list}, {"meshes", mesh_list}, {"written", written}});
    return;
  }
  std::cout << args.input << ", grid '" << info.name << "' (" << class_name(info.grid_class) << ")\n";
  print_row(std::cout, "planes at", std::string(args.world ? "world " : "normalised ") +
                                        format_number(options.position[0]) + ", " +
                                        format_number(options.position[1]) + ", " +
                                        format_number(options.position[2]));
  print_row(std::cout, "colours", map_name(options.colour.map) + ", " + format_number(f_min) + " .. " +
                                      format_number(f_max));
  for (const auto& path : written) std::cout << "wrote " << path.get<std::string>() << '\n';
}

}  // namespace

Command add_slice_command(CLI::App& parent) {
  auto args = std::make_shared<SliceArgs>();
  CLI::App* app = parent.add_subcommand(
      "slice", "Three orthogonal slices of a grid as PNG images and coloured meshes (Section 2.3)");
  app->footer(
      "Writes slice-x.png, slice-y.png, slice-z.png (the planes x = c1, y = c2, z = c3; colour bar "
      "on the right, top = highest value) and slice-planes.ply, slice-surfaces.ply (graphs of the "
      "slice functions), slice-curves.ply (the same graphs as curve networks) into DIR, created if "
      "missing. --at is normalised: 0..1 across the grid's active bounding box per axis; with "
      "--world it is in world units. Axes left out stay in the middle. Example: isoform slice "
      "smoke.vdb --at x=0.3,y=0.5,z=0.7 --res 256 --map viridis -o slices/");
  app->add_option("file", args->input, "Volume file (.vdb, .nrrd, .nhdr, .nii, .nii.gz)")->required();
  app->add_option("-o,--output", args->output, "Folder to write the images and meshes into")->required();
  app->add_option("--grid", args->grid, "Grid to slice (default: the first scalar grid)");
  app->add_option("--at", args->at, "Plane positions: x=C1,y=C2,z=C3 (or C1,C2,C3); default the middle");
  app->add_flag("--world", args->world, "--at is in world units instead of normalised 0..1");
  app->add_option("--res", args->resolution, "Samples along the longer side of each slice (default 256)");
  app->add_option("--height", args->height,
                  "Largest lift of the graphs off their planes, as a fraction of the domain's largest "
                  "extent (default 0.25)");
  app->add_flag("--no-bar", args->no_bar, "Leave the colour bar out of the images");
  add_colour_options(*app, args->colour, "viridis");
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args] { run_slice(*args); }};
}

}  // namespace isoform::cli
