// `isoform compare MESH [--reference in.vdb --iso V | --reference sphere|torus] -o study/`:
// the flat triangles, the Loop limit surface and the side-vertex surface
// (Chapter 6) of the same triangulation,
// measured at the same samples, written as report.json,
// samples.csv, report.md, one PLY tessellation per surface, and pictures:
// matplotlib plots and Blender renders with isophote stripes.
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.h"
#include "contouring.h"
#include "paths.h"
#include "progress.h"
#include "report.h"
#include "study_tools.h"

namespace isoform::cli {
namespace {

struct CompareArgs {
  std::string input, output, reference, grid;
  double iso = 0.0;
  bool has_iso = false;
  std::vector<double> centre;
  double radius = 0.0, minor_radius = 0.0;
  int level = 8, isolation = 6;
  long long table_triangles = 2000;
  bool smooth_corners = false, no_render = false, no_plots = false, no_side_vertex = false, json = false;
  ProgressOptions progress;
};

struct ReportDeleter {
  void operator()(isoform_compare_report* r) const { isoform_compare_report_free(r); }
};
using ReportPtr = std::unique_ptr<isoform_compare_report, ReportDeleter>;

isoform_compare_options options_of(const CompareArgs& a) {
  isoform_compare_options o;
  isoform_compare_options_default(&o);
  o.level = a.level;
  o.loop_isolation = a.isolation;
  o.loop_sharp_corners = a.smooth_corners ? 0 : 1;
  o.table_triangles = a.table_triangles;
  o.input_name = a.input.c_str();
  o.side_vertex = a.no_side_vertex ? 0 : 1;
  if (a.reference == "sphere") o.reference = ISOFORM_REFERENCE_SPHERE;
  if (a.reference == "torus") o.reference = ISOFORM_REFERENCE_TORUS;
  const bool given = !a.centre.empty() || a.radius > 0.0;
  if (given) {
    o.fit_reference = 0;
    for (size_t i = 0; i < a.centre.size() && i < 3; ++i) o.centre[i] = a.centre[i];
    if (a.radius > 0.0) o.radius = a.radius;
    if (a.minor_radius > 0.0) o.minor_radius = a.minor_radius;
    if (a.reference == "torus" && (a.radius <= 0.0 || a.minor_radius <= 0.0))
      throw Failure("--reference torus with given parameters needs --radius and --minor-radius");
    if (a.reference == "sphere" && a.radius <= 0.0) throw Failure("--reference sphere with --centre needs --radius");
  }
  o.isovalue = a.iso;
  return o;
}

// The pictures: plots (matplotlib) and renders (Blender), each optional.
void make_pictures(const CompareArgs& a, Json& summary) {
  const std::string scripts = study_scripts_folder();
  const std::string log = a.output + "/pictures.log";
  auto step = [&](const std::string& what, const std::string& program, const std::vector<std::string>& args) {
    std::string status;
    if (program.empty()) status = "skipped: program not found";
    else {
      std::vector<std::string> argv = {program};
      argv.insert(argv.end(), args.begin(), args.end());
      const int code = run_program(argv, log);
      status = code == 0 ? "made" : "skipped: " + program + " exited with " + std::to_string(code) + " (see pictures.log)";
    }
    summary["pictures"][what] = status;
    if (!a.progress.quiet && status != "made") std::cerr << "isoform: note: " << what << " " << status << '\n';
  };
  if (!a.no_plots)
    step("plots", find_program({"/usr/bin/python3"}), {scripts + "/plot_study.py", a.output});
  else
    summary["pictures"]["plots"] = "skipped: --no-plots";
  if (!a.no_render)
    step("renders", find_program({"blender"}),
         {"-b", "--factory-startup", "--python-exit-code", "1", "--python", scripts + "/render_study.py", "--", a.output});
  else
    summary["pictures"]["renders"] = "skipped: --no-render";
}

Json stats_json(const isoform_compare_stats& s) { return {{"max", s.max}, {"rms", s.rms}, {"count", s.count}}; }

void run_compare(const CompareArgs& a) {
  // Everything that can fail on the input happens before the folder is
  // touched, so a bad input leaves no study behind.
  isoform_compare_options o = options_of(a);
  MeshPtr mesh;
  {
    isoform_mesh* m = nullptr;
    check(isoform_mesh_load(a.input.c_str(), &m));
    mesh.reset(m);
  }
  VolumePtr volume;
  if (!a.reference.empty() && a.reference != "sphere" && a.reference != "torus") {
    volume = open_volume(a.reference);
    o.grid = find_grid(volume.get(), a.grid);
    if (!a.has_iso) {
      const isoform_grid_info info = grid_info(volume.get(), o.grid);
      o.isovalue = info.grid_class == ISOFORM_CLASS_LEVEL_SET ? 0.0 : 0.5 * (info.value_min + info.value_max);
      if (!a.progress.quiet)
        std::cerr << "isoform: note: reference isovalue " << format_number(o.isovalue) << " (--iso sets it)\n";
    }
  }
  isoform_compare_report* raw = nullptr;
  run_with_progress([&](isoform_progress* p) { return isoform_compare(mesh.get(), volume.get(), &o, p, &raw); },
                    a.progress);
  const ReportPtr report(raw);
  make_output_folder(a.output);
  check(isoform_compare_report_write(report.get(), a.output.c_str()));
  Json summary = {{"input", a.input}, {"output", a.output}, {"reference", isoform_compare_report_reference(report.get())}};
  for (int i = 0; i < isoform_compare_report_surface_count(report.get()); ++i) {
    const std::string name = isoform_compare_report_surface_name(report.get(), i);
    isoform_mesh* t = nullptr;
    check(isoform_compare_report_tessellation(report.get(), i, &t));
    const MeshPtr tess(t);
    save_mesh(tess.get(), a.output + "/surface-" + name + ".ply");
    isoform_compare_metrics m;
    check(isoform_compare_report_metrics(report.get(), i, &m));
    summary["surfaces"][name] = {{"deviation", stats_json(m.deviation)},
                                 {"data_point_error", stats_json(m.data_point_error)},
                                 {"normal_gap", stats_json(m.normal_gap)},
                                 {"mean_curvature_jump", stats_json(m.mean_curvature_jump)},
                                 {"seconds_per_million", m.seconds_per_million},
                                 {"tessellation_triangles", m.tessellation_triangles}};
  }
  const std::string notes = isoform_compare_report_notes(report.get());
  summary["notes"] = notes;
  if (!notes.empty() && !a.progress.quiet) std::cerr << "isoform: note: " << notes;
  make_pictures(a, summary);
  if (a.json) {
    print_json(summary);
    return;
  }
  std::cout << "wrote " << a.output << "/report.md, report.json, samples.csv\n";
  for (auto& [name, s] : summary["surfaces"].items())
    std::cout << "  " << name << ": normal gap max " << format_number(s["normal_gap"]["max"].get<double>())
              << " rad, error at data points max " << format_number(s["data_point_error"]["max"].get<double>())
              << (s["deviation"]["count"].get<long long>() > 0
                      ? ", deviation max " + format_number(s["deviation"]["max"].get<double>())
                      : std::string())
              << '\n';
  for (auto& [what, status] : summary["pictures"].items()) std::cout << "  " << what << ": " << status.get<std::string>() << '\n';
}

}  // namespace

Command add_compare_command(CLI::App& parent) {
  auto a = std::make_shared<CompareArgs>();
  CLI::App* app = parent.add_subcommand(
      "compare", "Measure the side-vertex surface, the Loop limit surface and the flat triangles of a mesh side by side");
  app->footer(
      "Samples every surface at the same barycentric lattice of each base triangle and writes "
      "report.json, samples.csv, report.md, surface-<name>.ply (each surface tessellated at the "
      "level), plots (matplotlib: curvature histograms, error plots) and renders with isophote "
      "stripes (Blender headless). Without python3-matplotlib or blender the pictures are skipped "
      "and the data files still written. The reference is a volume file (deviation "
      "|f - iso| / |grad f| in voxels), or an analytic sphere or torus around z (exact distance; "
      "centre and radii fitted to the vertices unless --centre/--radius/--minor-radius give them). "
      "Example: isoform compare reduced.ply --reference head.vdb --iso 0.5 -o study/");
  app->add_option("file", a->input, "Base mesh (.ply, .obj, .stl)")->required();
  app->add_option("-o,--output", a->output, "Folder for the study (created)")->required();
  app->add_option("--reference", a->reference, "sphere, torus, or a volume file (.vdb, .nrrd, .nii)");
  app->add_option("--grid", a->grid, "Grid of the reference volume (default: the first scalar grid)");
  app->add_option("--iso", a->iso, "Isovalue of the reference volume (default: 0 for level sets, else mid-range)")
      ->each([a](const std::string&) { a->has_iso = true; });
  app->add_option("--centre", a->centre, "Centre of the sphere or torus, x,y,z")->delimiter(',')->expected(3);
  app->add_option("--radius", a->radius, "Sphere radius, or torus major radius")->check(CLI::PositiveNumber);
  app->add_option("--minor-radius", a->minor_radius, "Torus tube radius")->check(CLI::PositiveNumber);
  app->add_option("--level", a->level, "Lattice level k: (k+1)(k+2)/2 samples per triangle (default 8)")
      ->check(CLI::Range(1, 64));
  app->add_option("--isolation", a->isolation, "Loop adaptive isolation level (default 6)")->check(CLI::Range(1, 10));
  app->add_flag("--smooth-corners", a->smooth_corners, "Loop: smooth valence-2 boundary corners");
  app->add_option("--csv-triangles", a->table_triangles, "Base triangles in samples.csv (default 2000)")
      ->check(non_negative_number());
  app->add_flag("--no-side-vertex", a->no_side_vertex, "Leave out the side-vertex surface");
  app->add_flag("--no-render", a->no_render, "Skip the Blender renders");
  app->add_flag("--no-plots", a->no_plots, "Skip the matplotlib plots");
  add_progress_flags(*app, a->progress);
  app->add_flag("--json", a->json, "Print one JSON object instead of text");
  return {app, [a] { run_compare(*a); }};
}

}  // namespace isoform::cli
