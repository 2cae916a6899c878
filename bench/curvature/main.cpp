// isoform_curvature_bench: command line, the run over every mesh, the
// targets' verdicts and the JSON report (bench/run-curvature.sh calls it).
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "curvature_bench.h"

namespace icb = isoform_curvature_bench;

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
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

// The targets (bench/curvature/README.md), judged on every mesh: the
// default at 1M vertices per second per core (one thread) and more accurate
// than every peer in H, K, k1 and k2; the seed's method at 5M with normals
// given.
icb::Json verdicts(const icb::Json& cases) {
  double default_rate = 1e300, seed_rate = 1e300;
  bool beats_peers = true;
  for (const icb::Json& c : cases) {
    const icb::Json& base = c["results"][0]["rms"];  // the default's row comes first
    for (const icb::Json& r : c["results"]) {
      const std::string m = r["method"];
      const double rate = r["one_thread"]["vertices_per_second_per_core_cpu"];
      if (m == "isoform quartic (default)") default_rate = std::min(default_rate, rate);
      if (m == "isoform seed, exact normals") seed_rate = std::min(seed_rate, rate);
      // RMS compared directly: the default's can be exactly 0 (k1 = 2.5 on
      // the regular torus is exact in float), where a ratio says nothing.
      if (m.rfind("isoform", 0) != 0)
        for (const char* q : {"H", "K", "k1", "k2"})
          beats_peers = beats_peers && double(r["rms"][q]) > double(base[q]);
    }
  }
  return icb::Json{{"default_vertices_per_second_per_core_min", default_rate},
                   {"default_at_least_1M", default_rate >= 1e6},
                   {"default_more_accurate_than_every_peer", beats_peers},
                   {"seed_exact_normals_vertices_per_second_per_core_min", seed_rate},
                   {"seed_exact_normals_at_least_5M", seed_rate >= 5e6}};
}

void write_json(const std::string& path, const icb::Json& report) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << report.dump(2) << "\n";
    if (!out) throw std::runtime_error("cannot write " + tmp);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw std::runtime_error("cannot rename " + tmp + " to " + path);
}

int run(const icb::Options& o, const std::string& command) {
  icb::Json report{{"date", utc_now()},
                   {"command", command},
                   {"rounds", o.rounds},
                   {"reps", o.reps},
                   {"load_average_start", load_average()}};
  std::printf("isoform_curvature_bench %s, load average %s\n", utc_now().c_str(), load_average().c_str());
  std::printf("Million vertices per second per core, from CPU time (all threads) and from wall time x threads,\n"
              "best of %d rounds x %d calls for isoform (its methods in turn in each round), %d for the peers;\n"
              "speed (CPU, 1 thread) and RMS as ratios against isoform's default in the same run; * = one and\n"
              "two threads gave different bits\n",
              o.rounds, o.reps, o.peer_reps);
  icb::Json cases = icb::Json::array();
  for (const std::string& s : o.shapes)
    for (double jitter : {0.0, o.jitter}) {
      const bool torus = s == "torus";
      const icb::Case c = icb::make_case(torus ? isoform::truth::Shape::Torus : isoform::truth::Shape::Ellipsoid,
                                         torus ? o.resolution_torus : o.resolution_ellipsoid, jitter);
      std::vector<icb::Result> results;
      std::vector<float> mesh_normals;
      icb::run_isoform(c, o, results, mesh_normals);
      if (o.vtk) icb::run_vtk(c, o, results);
      if (o.cgal) icb::run_cgal(c, o, 2, mesh_normals, results);
      if (o.cgal && o.cgal4) icb::run_cgal(c, o, 4, mesh_normals, results);
      icb::print_case(c, results);
      std::fflush(stdout);
      icb::Json j = icb::case_json(c, results);
      j["load_average_after"] = load_average();
      cases.push_back(j);
    }
  report["cases"] = cases;
  report["load_average_end"] = load_average();
  report["targets"] = verdicts(cases);
  const icb::Json& t = report["targets"];
  std::printf("\ntargets (worst mesh): default %.3f Mv/s/core (>= 1: %s), more accurate than every peer: %s;"
              " seed with exact normals %.3f Mv/s/core (>= 5: %s)\nload average at the end %s\n",
              double(t["default_vertices_per_second_per_core_min"]) / 1e6,
              t["default_at_least_1M"] ? "yes" : "no", t["default_more_accurate_than_every_peer"] ? "yes" : "no",
              double(t["seed_exact_normals_vertices_per_second_per_core_min"]) / 1e6,
              t["seed_exact_normals_at_least_5M"] ? "yes" : "no", load_average().c_str());
  if (!o.json_path.empty()) write_json(o.json_path, report);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"isoform_curvature_bench: isoform's surface curvature vs VTK vtkCurvatures and CGAL jet fitting"};
  icb::Options o;
  app.add_option("--json", o.json_path, "Write the report as JSON to this file");
  app.add_option("--reps", o.reps, "Timed calls per isoform method and thread count (the best counts)")
      ->check(CLI::Range(1, 20))
      ->capture_default_str();
  app.add_option("--rounds", o.rounds, "Rounds of isoform's methods called in turn (the best counts)")
      ->check(CLI::Range(1, 20))
      ->capture_default_str();
  app.add_option("--peer-reps", o.peer_reps, "The same for VTK and CGAL")->check(CLI::Range(1, 20))->capture_default_str();
  app.add_option("--torus-resolution", o.resolution_torus, "Points around the torus (x 0.6 around the tube)")
      ->check(CLI::Range(8, 4000))
      ->capture_default_str();
  app.add_option("--ellipsoid-resolution", o.resolution_ellipsoid, "Points around the ellipsoid's longest circle")
      ->check(CLI::Range(8, 4000))
      ->capture_default_str();
  app.add_option("--jitter", o.jitter, "Jitter of the second mesh of each shape, in edge lengths")
      ->check(CLI::Range(0.01, 0.4))
      ->capture_default_str();
  app.add_option("--cgal-rings", o.cgal_rings, "Rings of CGAL's neighbourhood")->check(CLI::Range(1, 5))->capture_default_str();
  app.add_option("--shapes", o.shapes, "Shapes to run")->check(CLI::IsMember({"torus", "ellipsoid"}))->capture_default_str();
  app.add_option("--cgal-stride", o.cgal_stride, "CGAL's one-thread time from every n-th vertex, scaled")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_flag_callback("--no-vtk", [&] { o.vtk = false; }, "Leave out VTK");
  app.add_flag_callback("--no-cgal", [&] { o.cgal = false; }, "Leave out CGAL");
  app.add_flag_callback("--no-cgal4", [&] { o.cgal4 = false; }, "Leave out CGAL's degree-4 jet");
  CLI11_PARSE(app, argc, argv);
  std::ostringstream command;
  for (int i = 0; i < argc; ++i) command << (i ? " " : "") << argv[i];
  try {
    return run(o, command.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "isoform_curvature_bench: %s\n", e.what());
    return 1;
  }
}
