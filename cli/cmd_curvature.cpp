// `isoform curvature MESH -o OUT`: principal curvatures of a triangle mesh
// (Chapter 4, Section 4.2) as PLY vertex properties and colours.
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.h"
#include "contouring.h"
#include "curvature_step.h"
#include "paths.h"

namespace isoform::cli {
namespace {

struct CurvatureArgs {
  std::string input, output;
  CurvatureSettings settings;
  int threads = 0;
  ProgressOptions progress;
  bool json = false;
};

MeshPtr load_mesh(const std::string& path) {
  isoform_mesh* mesh = nullptr;
  check(isoform_mesh_load(path.c_str(), &mesh));
  return MeshPtr(mesh);
}

void run_curvature(const CurvatureArgs& args) {
  check_output_path(args.input, args.output, {".ply"});
  const MeshPtr mesh = load_mesh(args.input);
  if (isoform_mesh_triangle_count(mesh.get()) == 0)
    throw Failure(args.input + ": the mesh has no triangles, so it has no curvature");
  double seconds = 0;
  try {
    seconds = compute_curvature(mesh.get(), args.settings, args.threads, args.progress);
  } catch (const Failure& failure) {
    // The library names its step ("curvature: triangle 2 ..."); the user
    // needs the file.
    const std::string message = failure.what(), library = "curvature: ";
    const bool named = message.rfind(library, 0) == 0;
    throw Failure(args.input + ": " + (named ? message.substr(library.size()) : message), failure.exit_code());
  }
  const double write_seconds = save_mesh(mesh.get(), args.output);
  if (args.json) {
    Json j = {{"input", args.input}, {"output", args.output}, {"curvature_seconds", seconds},
              {"write_seconds", write_seconds}};
    j["curvature"] = curvature_json(mesh.get());
    print_json(j);
    return;
  }
  std::cout << args.input << ": " << isoform_mesh_vertex_count(mesh.get()) << " vertices, "
            << isoform_mesh_triangle_count(mesh.get()) << " triangles\n";
  print_curvature(std::cout, mesh.get());
  print_row(std::cout, "time", format_seconds(seconds));
  std::cout << "wrote " << args.output << '\n';
}

}  // namespace

Command add_curvature_command(CLI::App& parent) {
  auto args = std::make_shared<CurvatureArgs>();
  CLI::App* app = parent.add_subcommand(
      "curvature", "Principal curvatures of a triangle mesh, written as PLY vertex properties");
  app->footer(
      "Writes per-vertex k1 k2 (k1 >= k2), mean, gauss, absolute (|k1|+|k2|), the principal "
      "directions d1x..d2z, curvature_flags, and red green blue alpha colours over a robust range "
      "(a diverging map centred on zero for signed quantities). Curvature is positive where the "
      "surface bends away from its normal. The mesh's normals orient it: PLY/OBJ normals when "
      "the file has them, else normals estimated from the mesh. Example: "
      "isoform curvature skull.ply -o curved.ply");
  app->add_option("file", args->input, "Mesh file (.ply, .obj, .stl)")->required();
  app->add_option("-o,--output", args->output, "PLY file to write")->required();
  add_curvature_options(*app, args->settings, "--method");
  app->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  add_progress_flags(*app, args->progress);
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args] { run_curvature(*args); }};
}

}  // namespace isoform::cli
