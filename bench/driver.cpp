// The `run` driver: one child process per (method, input), then the tables
// and the JSON report. Each child is this executable again (/proc/self/exe)
// with the `measure` sub-command; it writes its result object to a file.
#include <sys/wait.h>
#include <unistd.h>

#include <openvdb/version.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "bench.h"

namespace isoform_bench {

namespace fs = std::filesystem;

namespace {

struct Case {
  std::string name;
  std::string what;
  std::string vdb;
  double iso = 0.0;
  std::optional<RawLayout> raw;  // the same data as a dense scan
};

std::string exact(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

std::string joined(const std::array<int, 3>& v) {
  return std::to_string(v[0]) + "," + std::to_string(v[1]) + "," + std::to_string(v[2]);
}

std::string joined(const std::array<double, 3>& v) {
  return exact(v[0]) + "," + exact(v[1]) + "," + exact(v[2]);
}

// The one-minute load average: how busy the shared machine was.
double load_average() {
  std::ifstream in("/proc/loadavg");
  double one = 0.0;
  in >> one;
  return one;
}

std::string describe_status(int status) {
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "exit code " + std::to_string(WEXITSTATUS(status));
}

// Runs this executable with args; returns the result object the child wrote,
// or {"error": ...} if it failed or wrote nothing.
Json run_child(std::vector<std::string> args, const std::string& result_path) {
  fs::remove(result_path);
  args.insert(args.begin(), "isoform_bench");
  args.push_back("--result");
  args.push_back(result_path);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::cout.flush();
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid < 0) return Json{{"error", "fork failed"}};
  if (pid == 0) {
    execv("/proc/self/exe", argv.data());
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return Json{{"error", "waitpid failed"}};
  Json result;
  std::ifstream in(result_path);
  if (in) {
    try {
      in >> result;
    } catch (const std::exception& e) {
      result = Json{{"error", std::string("unreadable result: ") + e.what()}};
    }
  }
  const bool exited_ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!exited_ok && !result.contains("error")) result = Json{{"error", describe_status(status)}};
  if (exited_ok && result.is_null()) result = Json{{"error", "the child wrote no result"}};
  return result;
}

Json measure_in_child(const std::string& method, const Case& c, bool raw, int reps,
                      const std::string& work_dir) {
  std::vector<std::string> args = {"measure", "--method", method, "--iso", exact(c.iso)};
  args.insert(args.end(), {"--reps", std::to_string(reps)});
  if (raw) {
    const RawLayout& r = *c.raw;
    args.insert(args.end(), {"--raw", r.path, "--dims", joined(r.dims), "--type", r.type, "--spacing",
                             joined(r.spacing)});
  } else {
    args.insert(args.end(), {"--vdb", c.vdb});
  }
  std::cerr << "isoform_bench: " << c.name << ": " << method << " ..." << std::flush;
  const double load_before = load_average();
  Json result = run_child(args, work_dir + "/result.json");
  if (result.contains("error")) {
    std::cerr << " failed: " << result["error"].get<std::string>() << "\n";
    return result;
  }
  result["load_average"] = {load_before, load_average()};
  std::cerr << " best " << result["best_ms"].get<double>() << " ms, peak "
            << result["peak_kb"].get<long long>() / 1024 << " MB\n";
  return result;
}

// Rounds run every method once each, in turn, so that a slow spell on a
// shared machine hits all of them. The result kept is the round with the
// best time, with the highest peak of all rounds; a failure in any round
// stands.
void keep_best(Json& kept, const Json& round) {
  if (kept.contains("error")) return;
  if (kept.is_null() || round.contains("error")) {
    kept = round;
    if (!kept.contains("error")) kept["round_best_ms"] = Json::array({round["best_ms"]});
    return;
  }
  Json rounds = kept["round_best_ms"];
  rounds.push_back(round["best_ms"]);
  const long long peak = std::max(kept["peak_kb"].get<long long>(), round["peak_kb"].get<long long>());
  if (round["best_ms"].get<double>() < kept["best_ms"].get<double>()) kept = round;
  kept["round_best_ms"] = rounds;
  kept["peak_kb"] = peak;
}

bool ok(const Json& results, const std::string& method) {
  return results.contains(method) && !results[method].contains("error");
}

double mb(const Json& result) { return double(result["peak_kb"].get<long long>()) / 1024.0; }

std::string fixed(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

std::string grouped(long long v) {
  std::string digits = std::to_string(v);
  for (int at = int(digits.size()) - 3; at > 0; at -= 3) digits.insert(size_t(at), ",");
  return digits;
}

// A plain text table: columns right-aligned to their widest cell.
void print_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::vector<size_t> width(header.size());
  for (size_t c = 0; c < header.size(); ++c) width[c] = header[c].size();
  for (const auto& row : rows)
    for (size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  const auto line = [&](const std::vector<std::string>& cells) {
    for (size_t c = 0; c < cells.size(); ++c)
      std::printf(c == 0 ? "%-*s" : "  %*s", int(width[c]), cells[c].c_str());
    std::printf("\n");
  };
  line(header);
  for (const auto& row : rows) line(row);
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return buffer;
}

std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

std::vector<Case> cases(const PrepareOptions& p) {
  std::vector<Case> out;
  out.push_back({"cube", "cube.vdb, level set, iso 0", p.data_dir + "/cube.vdb", 0.0, std::nullopt});
  out.push_back({"smoke", "smoke.vdb, fog volume, iso 0.5", p.data_dir + "/smoke.vdb", 0.5, std::nullopt});
  if (p.sphere)
    out.push_back(
        {"sphere",
         "createLevelSetSphere radius " + std::to_string(p.sphere_radius) + " voxels, half width 3, iso 0",
         sphere_path(p.work_dir, p.sphere_radius), 0.0, std::nullopt});
  out.push_back({"headsq", "headsq 64x64x93 u16 (isoform convert to .vdb), iso 1150.5",
                 headsq_vdb_path(p.work_dir), 1150.5, headsq_layout(p.data_dir)});
  if (p.resample) {
    const RawLayout fine = resampled_layout(p.work_dir);
    out.push_back({"headsq-0.8",
                   "headsq resampled trilinearly to spacing 0.8 (" + std::to_string(fine.dims[0]) + "x" +
                       std::to_string(fine.dims[1]) + "x" + std::to_string(fine.dims[2]) +
                       " f32), iso 1150.5",
                   resampled_vdb_path(p.work_dir), 1150.5, fine});
  }
  return out;
}

// One input: every method, in rounds, and the ratios between them.
Json measure_case(const Case& c, const RunOptions& options, double base_mb) {
  std::vector<std::pair<std::string, bool>> methods = {{"isoform", false}, {"volume-to-mesh", false}};
  if (c.raw) {
    methods.emplace_back("isoform-raw", true);
#ifdef ISOFORM_BENCH_HAVE_VTK
    methods.emplace_back("flying-edges", true);
#endif
  }
  Json results;
  for (int round = 0; round < options.rounds; ++round)
    for (const auto& [method, raw] : methods)
      keep_best(results[method], measure_in_child(method, c, raw, options.reps, options.prepare.work_dir));

  Json entry{{"name", c.name}, {"input", c.what}, {"vdb", c.vdb}, {"iso", c.iso}, {"results", results}};
  if (c.raw) entry["raw"] = Json{{"path", c.raw->path}, {"samples", c.raw->sample_count()}};
  Json ratios = Json::object();
  // Net of the fixed cost of the bench process itself (see run_all).
  const auto net = [&](const Json& a, const Json& b) { return (mb(a) - base_mb) / (mb(b) - base_mb); };
  if (ok(results, "isoform") && ok(results, "volume-to-mesh")) {
    const Json& a = results["isoform"];
    const Json& b = results["volume-to-mesh"];
    entry["active_voxels"] = b["active_voxels"];
    // Same active voxels on both sides, so the throughput ratio is the
    // inverse ratio of the times.
    ratios["throughput_isoform_over_volume_to_mesh"] =
        b["best_ms"].get<double>() / a["best_ms"].get<double>();
    ratios["peak_isoform_over_volume_to_mesh"] = mb(a) / mb(b);
    ratios["peak_net_isoform_over_volume_to_mesh"] = net(a, b);
    ratios["to_first_mesh_volume_to_mesh_over_isoform"] =
        (b["load_ms"].get<double>() + b["first_ms"].get<double>()) /
        (a["load_ms"].get<double>() + a["first_ms"].get<double>());
  }
  if (ok(results, "isoform-raw") && ok(results, "flying-edges")) {
    const Json& a = results["isoform-raw"];
    const Json& b = results["flying-edges"];
    ratios["throughput_isoform_raw_over_flying_edges"] =
        b["best_ms"].get<double>() / a["best_ms"].get<double>();
    ratios["peak_isoform_raw_over_flying_edges"] = mb(a) / mb(b);
    ratios["peak_net_isoform_raw_over_flying_edges"] = net(a, b);
  }
  entry["ratios"] = ratios;
  return entry;
}

void print_tables(const Json& report) {
  const auto cell_ms = [](const Json& r, const char* m) {
    if (!r.contains(m)) return std::string("n/a");
    return ok(r, m) ? fixed(r[m]["best_ms"].get<double>(), 1) : std::string("failed");
  };
  const auto cell_mb = [](const Json& r, const char* m) {
    return ok(r, m) ? fixed(mb(r[m]), 0) : std::string("-");
  };
  const auto cell_count = [](const Json& r, const char* m, const char* field) {
    return ok(r, m) ? grouped(r[m]["mesh"][field].get<long long>()) : std::string("-");
  };
  const auto cell_ratio = [](const Json& ratios, const char* key) {
    return ratios.contains(key) ? fixed(ratios[key].get<double>(), 2) : std::string("-");
  };
  const Json& cases = report["cases"];
  std::vector<std::vector<std::string>> rows;

  std::printf(
      "\nisoform_bench %s, %d threads, best of %d timed calls (after one untimed call) x %d round(s)\n",
      report["date"].get<std::string>().c_str(), kThreads, report["timed_calls"].get<int>(),
      report["rounds"].get<int>());
  std::printf("%s, %d hardware threads, load average %.1f at start, %.1f at end\n",
              report["host"]["cpu"].get<std::string>().c_str(), report["host"]["hardware_threads"].get<int>(),
              report["load_average_start"].get<double>(), report["load_average_end"].get<double>());
  if (!report["baseline"].contains("error"))
    std::printf("peak memory of the bench process loading nothing: %.0f MB (included below)\n",
                mb(report["baseline"]));

  std::printf("\nSparse grids: isoform_contour (C API) vs openvdb::tools::volumeToMesh (adaptivity 0)\n");
  std::printf(
      "speed = isoform throughput / volumeToMesh throughput (active voxels per second; > 1: isoform "
      "faster)\n");
  std::printf(
      "mem = isoform peak / volumeToMesh peak (target <= 1.5); net: both less the bench process's own "
      "peak\n\n");
  for (const Json& e : cases) {
    const Json& r = e["results"];
    rows.push_back({e["name"].get<std::string>(),
                    e.contains("active_voxels") ? grouped(e["active_voxels"].get<long long>()) : "-",
                    cell_ms(r, "isoform"), cell_ms(r, "volume-to-mesh"),
                    cell_ratio(e["ratios"], "throughput_isoform_over_volume_to_mesh"),
                    cell_count(r, "isoform", "triangles"), cell_count(r, "volume-to-mesh", "quads"),
                    cell_mb(r, "isoform"), cell_mb(r, "volume-to-mesh"),
                    cell_ratio(e["ratios"], "peak_isoform_over_volume_to_mesh"),
                    cell_ratio(e["ratios"], "peak_net_isoform_over_volume_to_mesh")});
  }
  print_table({"input", "active voxels", "isoform ms", "VtM ms", "speed", "isoform tris", "VtM quads",
               "isoform MB", "VtM MB", "mem", "mem net"},
              rows);

  std::printf("\nFrom file to first mesh (load, then the first, untimed call)\n\n");
  rows.clear();
  for (const Json& e : cases) {
    const Json& r = e["results"];
    const auto part = [&](const char* m, const char* field) {
      return ok(r, m) ? fixed(r[m][field].get<double>(), 1) : std::string("-");
    };
    rows.push_back({e["name"].get<std::string>(), part("isoform", "load_ms"), part("isoform", "first_ms"),
                    part("volume-to-mesh", "load_ms"), part("volume-to-mesh", "first_ms"),
                    cell_ratio(e["ratios"], "to_first_mesh_volume_to_mesh_over_isoform")});
  }
  print_table({"input", "isoform open ms", "isoform 1st call ms", "VtM load ms", "VtM 1st call ms",
               "VtM total / isoform total"},
              rows);

  std::printf(
      "\nisoform's stages in one more call after the timed ones: wall time, and the highest resident set\n"
      "sampled (every ms, by a thread of the bench's own that no timed call shares the cores with)\n"
      "(from the progress sink; topology: neighbours, parts and the repair of vanished normals)\n\n");
  rows.clear();
  for (const Json& e : cases)
    for (const char* m : {"isoform", "isoform-raw"}) {
      const Json& r = e["results"];
      if (!ok(r, m)) continue;
      const Json& st = r[m]["stages"];
      std::vector<std::string> row = {e["name"].get<std::string>() + " (" + m + ")"};
      for (const char* stage : {"contour", "merge", "topology"})
        row.push_back(fixed(st[stage]["ms"].get<double>(), 1));
      row.push_back(fixed(r[m]["staged_ms"].get<double>(), 1));
      for (const char* stage : {"contour", "merge", "topology"})
        row.push_back(fixed(double(st[stage]["max_rss_kb"].get<long long>()) / 1024.0, 0));
      rows.push_back(row);
    }
  print_table(
      {"run", "bricks ms", "merge ms", "topology ms", "call ms", "bricks MB", "merge MB", "topology MB"},
      rows);

  std::printf("\nDense scans: isoform_volume_open_raw + isoform_contour vs vtkFlyingEdges3D (normals on)\n");
  std::printf(
      "speed = Flying Edges ms / isoform ms (same samples; > 1: isoform faster); mem = isoform / FE\n\n");
  rows.clear();
  for (const Json& e : cases) {
    if (!e.contains("raw")) continue;
    const Json& r = e["results"];
    rows.push_back({e["name"].get<std::string>(), grouped(e["raw"]["samples"].get<long long>()),
                    cell_ms(r, "isoform-raw"), cell_ms(r, "flying-edges"),
                    cell_ratio(e["ratios"], "throughput_isoform_raw_over_flying_edges"),
                    cell_count(r, "isoform-raw", "triangles"), cell_count(r, "flying-edges", "triangles"),
                    cell_mb(r, "isoform-raw"), cell_mb(r, "flying-edges"),
                    cell_ratio(e["ratios"], "peak_isoform_raw_over_flying_edges"),
                    cell_ratio(e["ratios"], "peak_net_isoform_raw_over_flying_edges")});
  }
  print_table({"input", "samples", "isoform ms", "FE ms", "speed", "isoform tris", "FE tris", "isoform MB",
               "FE MB", "mem", "mem net"},
              rows);

  std::printf(
      "\nisoform meshes (shared vertices, neighbours, parts, normals; volumeToMesh: points + quads)\n\n");
  rows.clear();
  for (const Json& e : cases)
    for (const char* m : {"isoform", "isoform-raw"}) {
      const Json& r = e["results"];
      if (!ok(r, m)) continue;
      const Json& s = r[m]["mesh"];
      rows.push_back({e["name"].get<std::string>() + " (" + m + ")", grouped(s["vertices"].get<long long>()),
                      grouped(s["parts"].get<long long>()), grouped(s["boundary_edges"].get<long long>()),
                      grouped(s["nonmanifold_edges"].get<long long>()),
                      grouped(s["degenerate_triangles"].get<long long>()),
                      grouped(s["ambiguous_faces"].get<long long>())});
    }
  print_table({"mesh", "vertices", "parts", "boundary edges", "non-manifold edges", "degenerate tris",
               "ambiguous faces"},
              rows);

  std::printf("\nInputs:\n");
  for (const Json& e : cases)
    std::printf("  %-11s %s\n", e["name"].get<std::string>().c_str(), e["input"].get<std::string>().c_str());

  bool printed_errors = false;
  for (const Json& e : cases)
    for (const auto& [method, result] : e["results"].items())
      if (result.contains("error")) {
        if (!printed_errors) std::printf("\nFailures:\n");
        printed_errors = true;
        std::printf("  %s / %s: %s\n", e["name"].get<std::string>().c_str(), method.c_str(),
                    result["error"].get<std::string>().c_str());
      }
}

}  // namespace

int run_all(const RunOptions& options) {
  const std::string& work = options.prepare.work_dir;
  fs::create_directories(work);

  std::vector<std::string> prepare_args = {"prepare",
                                           "--data",
                                           options.prepare.data_dir,
                                           "--work",
                                           work,
                                           "--sphere-radius",
                                           std::to_string(options.prepare.sphere_radius)};
  if (!options.prepare.sphere) prepare_args.push_back("--no-sphere");
  if (!options.prepare.resample) prepare_args.push_back("--no-resample");
  std::cerr << "isoform_bench: preparing inputs in " << work << "\n";
  const Json prepared = run_child(prepare_args, work + "/prepare.json");
  if (prepared.contains("error")) {
    std::cerr << "isoform_bench: prepare failed: " << prepared["error"].get<std::string>() << "\n";
    return 1;
  }

  Json report;
  report["date"] = utc_now();
  report["threads"] = kThreads;
  report["timed_calls"] = options.reps;
  report["rounds"] = options.rounds;
  report["host"] = Json{{"cpu", cpu_model()}, {"hardware_threads", std::thread::hardware_concurrency()}};
  report["versions"] = Json{{"isoform", isoform_version()}, {"openvdb", OPENVDB_LIBRARY_VERSION_STRING}};
  report["prepared"] = prepared;
  report["load_average_start"] = load_average();
  report["baseline"] = run_child({"measure", "--method", "baseline"}, work + "/result.json");
  // Every child is this executable, with OpenVDB, VTK and libisoform mapped:
  // the same fixed cost on both sides of each memory ratio. The "net" ratios
  // take it out, which matters for the small inputs.
  const bool have_baseline = !report["baseline"].contains("error");
  const double base_mb = have_baseline ? mb(report["baseline"]) : 0.0;

  report["cases"] = Json::array();
  for (const Case& c : cases(options.prepare)) report["cases"].push_back(measure_case(c, options, base_mb));
  report["load_average_end"] = load_average();
  for (const Json& entry : report["cases"])
    if (ok(entry["results"], "flying-edges")) {
      report["versions"]["vtk"] = entry["results"]["flying-edges"]["vtk_version"];
      report["versions"]["vtk_smp_backend"] = entry["results"]["flying-edges"]["smp_backend"];
    }

  print_tables(report);

  bool all_ok = have_baseline;
  for (const Json& entry : report["cases"])
    for (const auto& [method, result] : entry["results"].items())
      all_ok = all_ok && !result.contains("error");
  if (!options.json_path.empty()) {
    std::ofstream out(options.json_path);
    out << report.dump(2) << "\n";
    if (!out) {
      std::cerr << "isoform_bench: cannot write " << options.json_path << "\n";
      return 1;
    }
    std::printf("\nJSON report: %s\n", options.json_path.c_str());
  }
  return all_ok ? 0 : 1;
}

}  // namespace isoform_bench
