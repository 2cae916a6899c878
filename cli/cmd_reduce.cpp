// `isoform reduce MESH --keep 10% -o OUT`: data reduction by iterative
// triangle removal (Chapter 5): fewer triangles where the surface is flat.
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.h"
#include "contouring.h"
#include "part_step.h"
#include "paths.h"
#include "reduce_step.h"

namespace isoform::cli {
namespace {

struct ReduceArgs {
  std::string input, output, keep = "10%";
  ReduceSettings settings;
  ProgressOptions progress;
  PartSettings parts;
  bool json = false;
};

void run_reduce(ReduceArgs& args) {
  args.settings.keep_fraction = parse_fraction(args.keep, "--keep");
  check_output_path(args.input, args.output, {".ply", ".obj", ".stl"});
  isoform_mesh* raw = nullptr;
  check(isoform_mesh_load(args.input.c_str(), &raw));
  const MeshPtr mesh(raw);
  if (isoform_mesh_triangle_count(mesh.get()) == 0) throw Failure(args.input + ": the mesh has no triangles");
  isoform_part_filter_stats dropped{};
  if (args.parts.wanted()) dropped = drop_parts(mesh.get(), part_filter(args.parts, "", args.input));
  const double seconds = reduce_mesh(mesh.get(), args.settings, args.input, args.progress);
  const double write_seconds = save_mesh(mesh.get(), args.output);
  if (args.json) {
    Json j = {{"input", args.input}, {"output", args.output}, {"point", args.settings.point}};
    j.update(reduce_json(mesh.get(), seconds));
    if (args.settings.graph) j["graph_rms"] = graph_rms(mesh.get());
    j["parts"] = isoform_mesh_part_count(mesh.get());
    if (args.parts.wanted()) j.update(parts_json(dropped));
    j["write_seconds"] = write_seconds;
    print_json(j);
    return;
  }
  std::cout << args.input << ": reduced with the " << args.settings.point << " point\n";
  if (args.parts.wanted()) print_parts(std::cout, dropped);
  print_reduce(std::cout, mesh.get(), seconds);
  if (args.settings.graph) print_row(std::cout, "RMS height error", format_number(graph_rms(mesh.get())));
  std::cout << "wrote " << args.output << '\n';
}

}  // namespace

Command add_reduce_command(CLI::App& parent) {
  auto args = std::make_shared<ReduceArgs>();
  CLI::App* app = parent.add_subcommand(
      "reduce", "Remove triangles where the surface is flat (Chapter 5), keeping genus and parts");
  app->footer(
      "Removes the triangle of least weight (angle weight times the absolute curvature at its "
      "vertices) again and again, replacing it by one point fitted to its neighbourhood, until "
      "--keep of the triangles remain or --tolerance would be exceeded. Curvature is computed "
      "first when the file has none (the cubic fit; run isoform curvature first for another). The mesh must be manifold, consistently oriented, with "
      "finite coordinates and not overlap itself (else the first offender is named), unless "
      "--manifold-parts; with --graph every triangle must turn counterclockwise seen from +z. "
      "Example: isoform reduce skull.ply --keep 10% -o small.ply");
  app->add_option("file", args->input, "Mesh file (.ply, .obj, .stl)")->required();
  app->add_option("-o,--output", args->output, "Mesh file to write: .ply, .obj or .stl")->required();
  app->add_option("--keep", args->keep, "Triangles to keep: a percentage (10%) or a fraction (0.1); default 10%");
  add_part_options(*app, args->parts);
  app->add_option("--tolerance", args->settings.tolerance,
                  "Largest distance, in world units, of an original vertex from the reduced surface and of "
                  "a new point from the original (default 0: off)")
      ->check(non_negative_number());
  app->add_flag("--lock-boundary", args->settings.lock_boundary,
                "Never remove a triangle touching the mesh boundary (Remark 5.8)");
  app->add_option("--point", args->settings.point,
                  "Replacement point: quadratic (fit in the triangle's plane, 5.26) or quadric (5.30)")
      ->check(CLI::IsMember({"quadratic", "quadric"}));
  app->add_flag("--on-surface{false}", args->settings.refine_point,
                "Keep each new point on its fitted surface, as the seed does, instead of moving it "
                "to the least-squares best place for the original vertices: for surfaces that "
                "interpolate the vertices (isoform patch)");
  app->add_flag("--manifold-parts", args->settings.manifold_parts,
                "Instead of failing on bad input, reduce only the parts (triangles joined by edges) that "
                "pass every check and copy the others unchanged; --keep then counts the reduced parts' "
                "triangles. The summary says which parts were left alone and why");
  CLI::Option* graph = app->add_flag(
      "--graph", args->settings.graph,
      "The mesh is a height field z = f(x, y) (a terrain, the graph of a function, every triangle "
      "counterclockwise seen from +z): its (x, y) domain stays covered, new points move vertically, "
      "and the RMS height error at the original vertices is reported (Table 5.1)");
  app->add_option("--rms-tolerance", args->settings.rms_tolerance,
                  "With --graph: stop before the RMS height error at the original vertices exceeds this, "
                  "in world units (Remark 5.10; default 0: off)")
      ->check(non_negative_number())
      ->needs(graph);
  app->add_flag("--no-overlap", args->settings.prevent_overlap,
                "Refuse every removal whose new triangles would cross another triangle, so that the "
                "result does not overlap itself where two sheets lie close (thin bone) and can be "
                "reduced again; takes about 2-3 times as long");
  add_progress_flags(*app, args->progress);
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args] { run_reduce(*args); }};
}

}  // namespace isoform::cli
