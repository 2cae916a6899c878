// `isoform stack FILE -o OUT`: the transparency method of Section 2.2, three
// sets of coloured rectangles with alpha, sorted back to front for a view.
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

struct StackArgs {
  std::string input;
  std::string output;
  std::string grid;
  std::string n = "8";
  double t = 0.5;
  std::string view = "-1,-1,-1";
  ColourArgs colour;
  bool json = false;
};

void run_stack(const StackArgs& args) {
  check_output_path(args.input, args.output, {".ply", ".obj"});
  isoform_stack_options options;
  isoform_stack_options_default(&options);
  const std::vector<int> n = parse_integers(args.n, "--n", 3);
  const std::vector<double> view = parse_numbers(args.view, "--view", 3);
  for (int a = 0; a < 3; ++a) {
    options.n[a] = n[a];
    options.view[a] = view[a];
  }
  options.transparency = args.t;
  apply_colour_options(args.colour, options.colour);
  const VolumePtr volume = open_volume(args.input);
  const int grid = find_grid(volume.get(), args.grid);
  isoform_mesh* raw = nullptr;
  check(isoform_stack(volume.get(), grid, &options, &raw));
  const MeshPtr mesh(raw);
  check(isoform_mesh_save(mesh.get(), args.output.c_str()));
  const isoform_grid_info info = grid_info(volume.get(), grid);
  const Json m = coloured_mesh_json(mesh.get(), args.output);
  const long long rectangles = m["triangles"].get<long long>() / 2;
  if (args.json) {
    print_json({{"input", args.input}, {"grid", std::string(info.name)}, {"n", n}, {"t", args.t},
                {"alpha", 1.0 - args.t}, {"view", view}, {"rectangles", rectangles},
                {"map", map_name(options.colour.map)}, {"output", args.output}, {"mesh", m}});
    return;
  }
  std::cout << args.input << ", grid '" << info.name << "'\n";
  print_row(std::cout, "rectangles", std::to_string(rectangles) + ", back to front along " + args.view);
  print_row(std::cout, "transparency", format_number(args.t) + " (alpha " + format_number(1.0 - args.t) + ")");
  std::cout << "wrote " << args.output << '\n';
}

}  // namespace

Command add_stack_command(CLI::App& parent) {
  auto args = std::make_shared<StackArgs>();
  CLI::App* app = parent.add_subcommand(
      "stack", "Transparency stack: three sets of coloured rectangles with alpha (Section 2.2), as PLY");
  app->footer(
      "The grid is evaluated on (n+1)^3 points over its active bounding box; the rectangles "
      "parallel to the xy-, xz- and yz-planes get the colours of their corners and alpha = 1 - t, "
      "and are written back to front along --view (the direction from the eye into the scene), "
      "by the depth of each rectangle's corner nearest the eye. Example: isoform stack smoke.vdb "
      "--n 8 --t 0.5 --view -1,-1,-1 -o stack.ply");
  app->add_option("file", args->input, "Volume file (.vdb, .nrrd, .nhdr, .nii, .nii.gz)")->required();
  app->add_option("-o,--output", args->output, "Mesh file to write: .ply (with colours and alpha) or .obj")
      ->required();
  app->add_option("--grid", args->grid, "Grid to show (default: the first scalar grid)");
  app->add_option("--n", args->n, "Cells of the evaluation grid NX,NY,NZ or N (default 8)");
  app->add_option("--t", args->t, "Transparency t in [0, 1]: 0 opaque, alpha = 1 - t (default 0.5)");
  app->add_option("--view", args->view, "Viewing direction X,Y,Z, eye into scene (default -1,-1,-1)");
  add_colour_options(*app, args->colour, "viridis");
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args] { run_stack(*args); }};
}

}  // namespace isoform::cli
