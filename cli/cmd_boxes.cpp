// `isoform boxes FILE -o OUT`: the domain-subdivision subvolumes of Section
// 2.2, Gouraud-coloured, over the grid's domain or a spherical uvw domain.
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

struct BoxesArgs {
  std::string input;
  std::string output;
  std::string grid;
  std::string q = "5";
  std::string gap = "1";
  std::string face_cells = "1";
  bool centroid_lines = false;
  std::string domain = "box";
  std::string uvw_min, uvw_max, centre;
  ColourArgs colour;
  bool json = false;
};

void run_boxes(const BoxesArgs& args) {
  check_output_path(args.input, args.output, {".ply", ".obj"});
  isoform_boxes_options options;
  isoform_boxes_options_default(&options);
  const std::vector<int> q = parse_integers(args.q, "--q", 3);
  const std::vector<double> gap = parse_numbers(args.gap, "--gap", 3);
  const std::vector<int> cells = parse_integers(args.face_cells, "--face-cells", 2);
  for (int a = 0; a < 3; ++a) {
    options.q[a] = q[a];
    options.gap[a] = gap[a];
  }
  options.face_cells[0] = cells[0];
  options.face_cells[1] = cells[1];
  options.centroid_lines = args.centroid_lines;
  options.domain = args.domain == "spherical" ? ISOFORM_DOMAIN_SPHERICAL : ISOFORM_DOMAIN_BOX;
  auto set3 = [](const std::string& text, const char* name, double* out) {
    if (text.empty()) return;
    const std::vector<double> v = parse_numbers(text, name, 3);
    for (int a = 0; a < 3; ++a) out[a] = v[a];
  };
  set3(args.uvw_min, "--uvw-min", options.uvw_min);
  set3(args.uvw_max, "--uvw-max", options.uvw_max);
  set3(args.centre, "--centre", options.centre);
  apply_colour_options(args.colour, options.colour);
  const VolumePtr volume = open_volume(args.input);
  const int grid = find_grid(volume.get(), args.grid);
  isoform_mesh* raw = nullptr;
  check(isoform_boxes(volume.get(), grid, &options, &raw));
  const MeshPtr mesh(raw);
  check(isoform_mesh_save(mesh.get(), args.output.c_str()));
  const isoform_grid_info info = grid_info(volume.get(), grid);
  Json m = coloured_mesh_json(mesh.get(), args.output);
  if (args.json) {
    print_json({{"input", args.input}, {"grid", std::string(info.name)}, {"domain", args.domain},
                {"q", q}, {"gap", gap}, {"face_cells", cells}, {"subvolumes", q[0] * q[1] * q[2]},
                {"map", map_name(options.colour.map)}, {"output", args.output}, {"mesh", m}});
    return;
  }
  std::cout << args.input << ", grid '" << info.name << "', " << args.domain << " domain\n";
  print_row(std::cout, "subvolumes", std::to_string(q[0] * q[1] * q[2]) + " (" + std::to_string(q[0]) + " x " +
                                         std::to_string(q[1]) + " x " + std::to_string(q[2]) + ")");
  print_row(std::cout, "triangles", std::to_string(m["triangles"].get<long long>()));
  std::cout << "wrote " << args.output << '\n';
}

}  // namespace

Command add_boxes_command(CLI::App& parent) {
  auto args = std::make_shared<BoxesArgs>();
  CLI::App* app = parent.add_subcommand(
      "boxes", "Domain-subdivision subvolumes with Gouraud-coloured faces (Section 2.2), as PLY");
  app->footer(
      "Subvolume corners x_r = x_min + r (1 + a) dx, dx = (x_max - x_min) / (q + a (q - 1)) per "
      "axis, over the grid's active bounding box, or over uvw for --domain spherical: (x,y,z) = "
      "centre + (u cos v, u sin v cos w, u sin v sin w), by default u 0..1, v 0..pi, w 0..3pi/2 "
      "(Figure 2.4). PLY vertices carry red green blue alpha; the face property part is the "
      "subvolume. Example: isoform boxes gaussians.vdb --q 5,5,5 --gap 1 -o boxes.ply");
  app->add_option("file", args->input, "Volume file (.vdb, .nrrd, .nhdr, .nii, .nii.gz)")->required();
  app->add_option("-o,--output", args->output, "Mesh file to write: .ply (with colours) or .obj")->required();
  app->add_option("--grid", args->grid, "Grid to show (default: the first scalar grid)");
  app->add_option("--q", args->q, "Subvolumes per axis QX,QY,QZ or Q (default 5)");
  app->add_option("--gap", args->gap, "Gap over edge length per axis AX,AY,AZ or A (default 1)");
  app->add_option("--face-cells", args->face_cells, "K,L Gouraud cells per face, or K (default 1: corners only)");
  app->add_flag("--centroid-lines", args->centroid_lines, "Add edges between neighbouring subvolume centroids");
  app->add_option("--domain", args->domain, "box (default) or spherical")
      ->check(CLI::IsMember({"box", "spherical"}));
  app->add_option("--uvw-min", args->uvw_min, "Spherical: lower U,V,W (default 0,0,0)");
  app->add_option("--uvw-max", args->uvw_max, "Spherical: upper U,V,W (default 1,pi,3pi/2)");
  app->add_option("--centre", args->centre, "Spherical: world X,Y,Z of u = 0 (default 0,0,0)");
  add_colour_options(*app, args->colour, "green-white");
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args] { run_boxes(*args); }};
}

}  // namespace isoform::cli
