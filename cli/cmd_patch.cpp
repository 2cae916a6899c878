// `isoform patch MESH --level K -o OUT`: the tangent-plane-continuous
// side-vertex surface of Chapter 6 over a triangle mesh with normals,
// tessellated into a watertight mesh with the surface's exact normals.
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.h"
#include "contouring.h"
#include "paths.h"
#include "report.h"

namespace isoform::cli {
namespace {

struct PatchArgs {
  std::string input, output;
  int level = 3;
  std::string blend = "squared";
  std::string tension = "auto";
  ProgressOptions progress;
  bool json = false;
};

struct PatchDeleter {
  void operator()(isoform_patch* p) const { isoform_patch_free(p); }
};

// "auto" is 0 for the library; otherwise a positive number.
double parse_tension(const std::string& text) {
  if (text == "auto") return 0.0;
  size_t used = 0;
  double w = 0.0;
  try {
    w = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(w > 0.0) || !std::isfinite(w))
    throw Failure("--tension must be 'auto' or a positive weight omega, not '" + text + "'");
  return w;
}

Json patch_stats_json(const isoform_patch_stats& s) {
  return {{"triangles", s.triangles},
          {"edges", s.edges},
          {"nonconvex_edges", s.nonconvex_edges},
          {"opposite_normal_edges", s.opposite_normal_edges},
          {"fallback_plane_edges", s.fallback_plane_edges}};
}

void run_patch(const PatchArgs& args) {
  check_output_path(args.input, args.output, {".ply", ".obj", ".stl"});
  isoform_patch_options o;
  isoform_patch_options_default(&o);
  o.blend = args.blend == "printed" ? ISOFORM_PATCH_BLEND_PRINTED : ISOFORM_PATCH_BLEND_SQUARED;
  o.tension = parse_tension(args.tension);
  isoform_mesh* raw = nullptr;
  check(isoform_mesh_load(args.input.c_str(), &raw));
  const MeshPtr mesh(raw);
  if (isoform_mesh_triangle_count(mesh.get()) == 0)
    throw Failure(args.input + ": the mesh has no triangles, so it has no surface");
  const bool estimated = isoform_mesh_normals_estimated(mesh.get()) != 0;
  if (estimated && !args.progress.quiet)
    std::cerr << "isoform: " << args.input
              << " has no vertex normals; using normals estimated from the mesh (least squares on each "
                 "vertex's one-ring)\n";
  const auto start = std::chrono::steady_clock::now();
  isoform_patch* patch_raw = nullptr;
  isoform_status status = isoform_patch_create(mesh.get(), &o, &patch_raw);
  if (status != ISOFORM_OK) throw Failure(args.input + ": " + isoform_last_error());
  const std::unique_ptr<isoform_patch, PatchDeleter> patch(patch_raw);
  isoform_mesh* out_raw = nullptr;
  run_with_progress([&](isoform_progress* p) { return isoform_patch_tessellate(patch.get(), args.level, p, &out_raw); },
                    args.progress);
  const MeshPtr out(out_raw);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double write_seconds = save_mesh(out.get(), args.output);
  isoform_patch_stats ps;
  check(isoform_patch_stats_get(patch.get(), &ps));
  const isoform_mesh_stats in_stats = mesh_stats(mesh.get()), out_stats = mesh_stats(out.get());
  if (args.json) {
    Json j = {{"input", args.input}, {"output", args.output}, {"level", args.level}, {"blend", args.blend},
              {"tension", args.tension}, {"normals_estimated", estimated}};
    j["input_mesh"] = mesh_json(in_stats);
    j["patch"] = patch_stats_json(ps);
    j["mesh"] = mesh_json(out_stats);
    j["patch_seconds"] = seconds;
    j["write_seconds"] = write_seconds;
    print_json(j);
    return;
  }
  std::cout << args.input << ": " << in_stats.vertices << " vertices, " << in_stats.triangles << " triangles"
            << (estimated ? " (normals estimated)" : "") << '\n';
  print_row(std::cout, "blend", args.blend);
  print_row(std::cout, "tension", args.tension);
  print_row(std::cout, "non-convex edges", std::to_string(ps.nonconvex_edges) + " of " + std::to_string(ps.edges));
  print_row(std::cout, "level", std::to_string(args.level) + " (" + std::to_string(1 << args.level) +
                                    " steps per edge)");
  print_mesh(std::cout, out_stats);
  print_row(std::cout, "time", format_seconds(seconds));
  std::cout << "wrote " << args.output << '\n';
}

}  // namespace

Command add_patch_command(CLI::App& parent) {
  auto args = std::make_shared<PatchArgs>();
  CLI::App* app = parent.add_subcommand(
      "patch", "Smooth tangent-plane-continuous surface over a triangle mesh (Chapter 6), tessellated");
  app->footer(
      "Builds the side-vertex surface of Hamann (1991), Chapter 6: through every vertex with its "
      "normal, tangent-plane continuous across every edge, from degree-elevated conics. Each "
      "triangle becomes 4^level triangles; samples on shared edges are computed once, so a closed "
      "input gives a closed output. Vertex normals are the surface's exact normals. Input normals "
      "come from the file (PLY/OBJ) or, when it has none, are estimated from the mesh. Example: "
      "isoform patch reduced.ply --level 4 -o smooth.ply");
  app->add_option("file", args->input, "Mesh file with normals (.ply, .obj, .stl)")->required();
  app->add_option("-o,--output", args->output, "Mesh file to write (.ply, .obj, .stl)")->required();
  app->add_option("--level", args->level, "Subdivision level: 2^level steps per triangle edge, 0..10 (default 3)")
      ->check(CLI::Range(0, 10));
  app->add_option("--blend", args->blend,
                  "Weights of the building blocks: squared (u_j u_k)^2, Theorem 6.1 (iii) (default), or "
                  "printed u_j u_k as in (6.2)")
      ->check(CLI::IsMember({"printed", "squared"}));
  app->add_option("--tension", args->tension,
                  "Conic weight omega: auto = sin(gamma/2) of Theorem 6.3 (default), or a positive number "
                  "(lower pulls the surface toward the triangles; never above auto)");
  add_progress_flags(*app, args->progress);
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args] { run_patch(*args); }};
}

}  // namespace isoform::cli
