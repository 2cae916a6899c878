// isoform_reduce_bench: command line, the run over inputs, targets and
// methods, the two targets judged, the Markdown and JSON reports
// (bench/run-reduce.sh calls it).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>

#include <CLI/CLI.hpp>
#include <OpenMesh/Core/System/config.h>
#include <meshoptimizer.h>
#include <tbb/global_control.h>

#include "reduce_bench.h"

namespace irb = isoform_reduce_bench;

namespace {

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return in ? a + " " + b + " " + c : "unknown";
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&t));
  return buf;
}

void write_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + tmp);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw std::runtime_error("cannot rename " + tmp + " to " + path);
}

// A ratio for the table: three digits, or n/a when a side did not run.
std::string number(double x) {
  if (std::isnan(x)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

const irb::Row* find(const std::vector<irb::Row>& rows, double percent, const std::string& method) {
  for (const irb::Row& r : rows)
    if (r.run.percent == percent && r.run.method == method && r.run.failure.empty()) return &r;
  return nullptr;
}

// The targets (bench/README.md, "Reduction"): on the smooth graph at 90%
// removed, isoform's maximum and RMS error at most OpenMesh's; on every
// input and target, isoform's wall time at most 3 times meshoptimizer's.
std::string verdicts(const std::vector<irb::Input>& inputs, const std::vector<std::vector<irb::Row>>& all,
                     irb::Json& out) {
  std::string text = "| input | removed | isoform max / OpenMesh max | isoform RMS / OpenMesh RMS | error target met |"
                     " isoform time / meshopt time, wall | CPU | time target (<= 3) met, wall | CPU |\n"
                     "|---|---:|---:|---:|---|---:|---:|---|---|\n";
  out = irb::Json::array();
  for (size_t i = 0; i < inputs.size(); ++i)
    for (const irb::Row& r : all[i]) {
      if (r.run.method != "isoform") continue;
      const irb::Row* om = find(all[i], r.run.percent, "OpenMesh quadric");
      const irb::Row* mo = find(all[i], r.run.percent, "meshoptimizer");
      const bool ran = r.run.failure.empty();
      char line[512];
      std::string error_ok = "n/a", time_ok = "n/a", cpu_ok = "n/a";
      double max_ratio = NAN, rms_ratio = NAN, time_ratio = NAN, cpu_ratio = NAN;
      if (ran && om) {
        max_ratio = r.m.error.max() / om->m.error.max();
        rms_ratio = r.m.error.rms() / om->m.error.rms();
        error_ok = r.m.error.max() <= om->m.error.max() && r.m.error.rms() <= om->m.error.rms() ? "yes" : "no";
        const bool judged = inputs[i].name == "graph" && r.run.percent == 90;
        if (!judged) error_ok += " (not a target)";
      }
      if (ran && mo) {
        time_ratio = r.run.time.wall / mo->run.time.wall;
        cpu_ratio = r.run.time.cpu / mo->run.time.cpu;
        time_ok = time_ratio <= 3 ? "yes" : "no";
        cpu_ok = cpu_ratio <= 3 ? "yes" : "no";
      }
      std::snprintf(line, sizeof line, "| %s | %g%% | %s | %s | %s | %s | %s | %s | %s |\n", inputs[i].name.c_str(),
                    r.run.percent, number(max_ratio).c_str(), number(rms_ratio).c_str(), error_ok.c_str(),
                    number(time_ratio).c_str(), number(cpu_ratio).c_str(), time_ok.c_str(), cpu_ok.c_str());
      text += line;
      out.push_back(irb::Json{{"input", inputs[i].name}, {"percent_removed", r.run.percent},
                              {"max_over_openmesh", max_ratio}, {"rms_over_openmesh", rms_ratio},
                              {"time_over_meshopt", time_ratio}, {"cpu_over_meshopt", cpu_ratio},
                              {"error_met", error_ok}, {"time_met", time_ok}, {"cpu_met", cpu_ok}});
    }
  if (out.empty()) text += "| (isoform_reduce did not run: no verdict) | | | | | | | | |\n";
  return text;
}

// Every method's runs at one target, the methods called in turn: round r
// calls each method once, and each keeps its best time over the rounds, so
// a slow phase of the shared host weighs on all of them alike.
std::vector<irb::Row> interleaved_runs(const irb::Input& in, double percent, const irb::Options& o) {
  irb::Options once = o;
  once.reps = 1;
  std::vector<irb::Row> rows(o.methods.size());
  for (int round = 0; round < o.reps; ++round)
    for (size_t k = 0; k < o.methods.size(); ++k) {
      const std::string& method = o.methods[k];
      irb::Run run = method == "isoform"    ? irb::run_isoform(in, percent, once)
                     : method == "openmesh" ? irb::run_openmesh(in, percent, once)
                                            : irb::run_meshopt(in, percent, once);
      if (round > 0 && rows[k].run.failure.empty()) {
        run.time.wall = std::min(run.time.wall, rows[k].run.time.wall);
        run.time.cpu = std::min(run.time.cpu, rows[k].run.time.cpu);
      }
      rows[k].run = std::move(run);
    }
  for (irb::Row& row : rows)
    if (row.run.failure.empty()) row.m = irb::measure(in, row.run, o);
  return rows;
}

int run(const irb::Options& o, const std::string& command) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
  const std::string start = utc_now(), load_start = load_average();
  std::fprintf(stderr, "isoform_reduce_bench %s, load average %s; isoform_reduce %s\n", start.c_str(),
               load_start.c_str(), irb::isoform_reduce_available() ? "present" : "NOT in this build");
  std::vector<irb::Input> inputs;
  std::vector<std::vector<irb::Row>> all;
  irb::Json report{{"date", start}, {"command", command}, {"load_average_start", load_start},
                   {"samples_per_side", o.samples}, {"reps", o.reps}, {"lock_boundary", o.lock_boundary},
                   {"openmesh", OM_VERSION}, {"meshoptimizer", MESHOPTIMIZER_VERSION}};
  for (const std::string& name : o.inputs) {
    irb::Input in = name == "graph" ? irb::make_graph(o) : irb::make_contour(o);
    irb::prepare_reference(in, o);
    if (!o.save_inputs.empty()) irb::save_input(in, o.save_inputs + "/" + in.name + ".ply");
    std::fprintf(stderr, "%s: %zu triangles, %zu vertices, diagonal %.4g (%s)\n", in.name.c_str(),
                 in.mesh.triangle_count(), in.mesh.vertex_count(), in.diagonal, in.what.c_str());
    std::vector<irb::Row> rows;
    for (double p : o.percents)
      for (irb::Row& row : interleaved_runs(in, p, o)) {
        std::fprintf(stderr, "  %g%% %-17s %8zu triangles %8.3f s  max %.3g rms %.3g  %s\n", p,
                     row.run.method.c_str(), row.run.result.triangle_count(), row.run.time.wall, row.m.error.max(),
                     row.m.error.rms(), row.run.failure.c_str());
        rows.push_back(std::move(row));
      }
    inputs.push_back(std::move(in));
    all.push_back(std::move(rows));
  }
  std::ostringstream md;
  md << "# Reduction benchmark: isoform against OpenMesh and meshoptimizer\n\n"
     << "Written by `bench/run-reduce.sh` (`" << command << "`), " << start << " to " << utc_now()
     << ", load average " << load_start << " at the start and " << load_average()
     << " at the end (1, 5, 15 minutes; 2 cores shared with other work: only ratios within one run mean much). "
     << "OpenMesh " << (OM_VERSION >> 16) << "." << ((OM_VERSION >> 8) & 0xff) << ", meshoptimizer "
     << "0." << MESHOPTIMIZER_VERSION / 10 << "; isoform_reduce "
     << (irb::isoform_reduce_available() ? "present" : "**not in this build: peers only**") << ". Boundary: "
     << (!o.lock_boundary ? "free for every method"
         : o.isoform_lock_boundary
             ? "OpenMesh and meshoptimizer lock the boundary vertices, isoform its boundary triangles (lock_boundary)"
             : "OpenMesh and meshoptimizer lock the boundary vertices; isoform keeps a graph's domain covered "
               "(its graph option: boundary points may go along the straight border)")
     << ". Time: the best of " << o.reps
     << " call(s), the methods' calls in turn, wall clock, building each library's mesh structure excluded; isoform's includes the "
        "curvature it computes. Error: two-sided sampled distance to the original surface ("
     << o.samples << " area samples per surface and side, plus every vertex for the maximum), "
        "max and RMS the larger of the two sides; diag is the original's bounding-box diagonal. "
        "See bench/README.md for the method.\n\n";
  for (size_t i = 0; i < inputs.size(); ++i) {
    md << "## " << inputs[i].name << ": " << inputs[i].mesh.triangle_count() << " triangles\n\n"
       << inputs[i].what << "; " << inputs[i].mesh.vertex_count() << " vertices, bounding-box diagonal "
       << inputs[i].diagonal << ", area " << inputs[i].samples.area << "; " << inputs[i].stats.boundary_edges
       << " boundary and " << inputs[i].stats.nonmanifold_edges << " non-manifold edges, Euler characteristic "
       << inputs[i].stats.euler_characteristic << ", " << inputs[i].stats.parts << " part(s).\n\n"
       << irb::markdown_table(inputs[i], all[i]) << "\n";
    report["inputs"].push_back(irb::input_json(inputs[i], all[i]));
  }
  irb::Json targets;
  md << "## Targets\n\nError: at most OpenMesh quadric's (max and RMS) at 90% on the smooth graph. "
        "Time: at most 3 times meshoptimizer's.\n\n"
     << verdicts(inputs, all, targets);
  report["targets"] = targets;
  report["load_average_end"] = load_average();
  std::printf("%s", md.str().c_str());
  if (!o.markdown_path.empty()) write_atomically(o.markdown_path, md.str());
  if (!o.json_path.empty()) write_atomically(o.json_path, report.dump(2) + "\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"isoform_reduce_bench: isoform_reduce vs OpenMesh's quadric decimater and meshopt_simplify"};
  irb::Options o;
  o.data_dir = ISOFORM_BENCH_SHARED_DATA;
  if (const char* d = std::getenv("ISOFORM_SHARED_DATA")) o.data_dir = d;
  app.add_option("--data", o.data_dir, "Folder with headsq_64x64x93_u16le.raw")->capture_default_str();
  app.add_option("--inputs", o.inputs, "Inputs to run")->check(CLI::IsMember({"graph", "contour"}))->capture_default_str();
  app.add_option("--methods", o.methods, "Methods to run")
      ->check(CLI::IsMember({"isoform", "openmesh", "meshopt"}))
      ->capture_default_str();
  app.add_option("--percents", o.percents, "Percentages of the triangles to remove")
      ->check(CLI::Range(0.0, 99.99))
      ->capture_default_str();
  app.add_option("--graph", o.graph, "Table 4.1 function of the graph input")->capture_default_str();
  app.add_option("--knots", o.graph_knots, "Graph knots per side")->check(CLI::Range(3, 4000))->capture_default_str();
  app.add_option("--spacing", o.contour_spacing, "headsq resampling spacing (world units)")
      ->check(CLI::Range(0.3, 4.0))
      ->capture_default_str();
  app.add_option("--iso", o.contour_iso, "headsq isovalue")->capture_default_str();
  app.add_option("--samples", o.samples, "Area samples per surface and side")->check(CLI::Range(1000, 20000000))->capture_default_str();
  app.add_option("--reps", o.reps, "Timed calls per method and target, the methods in turn (the best counts)")->check(CLI::Range(1, 10))->capture_default_str();
  app.add_flag_callback("--free-boundary", [&] { o.lock_boundary = false; },
                        "Let every method move or remove boundary vertices (default: all lock them)");
  app.add_flag("--isoform-lock-boundary", o.isoform_lock_boundary,
               "isoform keeps the border by lock_boundary (no triangle touching it goes), not its graph option");
  app.add_option("--markdown", o.markdown_path, "Write the tables as Markdown to this file");
  app.add_option("--json", o.json_path, "Write the report as JSON to this file");
  app.add_option("--save-inputs", o.save_inputs, "Also write each input mesh as FOLDER/<input>.ply (to profile isoform reduce)");
  CLI11_PARSE(app, argc, argv);
  std::ostringstream command;
  command << "isoform_reduce_bench";
  for (int i = 1; i < argc; ++i) command << " " << argv[i];
  try {
    return run(o, command.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "isoform_reduce_bench: %s\n", e.what());
    return 1;
  }
}
