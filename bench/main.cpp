// isoform_bench: command line. `run` is what bench/run.sh calls; `prepare`
// and `measure` are the sub-commands `run` starts in child processes.
#include <tbb/global_control.h>

#include <fstream>

#include <CLI/CLI.hpp>

#include "bench.h"

namespace {

using isoform_bench::Json;

// Writes the child's result object; the driver reads it after the child ends.
int finish(const std::string& path, const Json& result, int code) {
  std::ofstream out(path);
  out << result.dump() << "\n";
  return out ? code : 1;
}

template <class Body>
int run_as_child(const std::string& result_path, Body&& body) {
  try {
    return finish(result_path, body(), 0);
  } catch (const std::exception& e) {
    return finish(result_path, Json{{"error", e.what()}}, 1);
  }
}

void add_input_options(CLI::App& app, isoform_bench::PrepareOptions& p) {
  app.add_option("--sphere-radius", p.sphere_radius,
                 "Radius in voxels of the generated level-set sphere (half width 3)")
      ->capture_default_str();
  app.add_flag_callback(
      "--no-sphere", [&p] { p.sphere = false; }, "Leave out the large level-set sphere");
  app.add_flag_callback(
      "--no-resample", [&p] { p.resample = false; }, "Leave out the resampled headsq");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"isoform_bench: isoform's contour vs OpenVDB volumeToMesh and VTK Flying Edges"};
  app.require_subcommand(1);

  isoform_bench::RunOptions run;
  CLI::App* run_cmd = app.add_subcommand("run", "Measure every method on every input, print the tables");
  run_cmd->add_option("--data", run.prepare.data_dir, "Folder with the real test data (../shared/data)")
      ->required();
  run_cmd->add_option("--work", run.prepare.work_dir, "Folder for generated inputs and child results")
      ->required();
  run_cmd->add_option("--json", run.json_path, "Write the report as JSON to this file")->required();
  run_cmd->add_option("--reps", run.reps, "Timed calls per method and input (after one untimed call)")
      ->check(CLI::Range(1, 20))
      ->capture_default_str();
  run_cmd
      ->add_option("--rounds", run.rounds,
                   "Rounds of all methods in turn; the best round counts (for noisy machines)")
      ->check(CLI::Range(1, 10))
      ->capture_default_str();
  add_input_options(*run_cmd, run.prepare);

  isoform_bench::PrepareOptions prepare;
  std::string result_path;
  CLI::App* prepare_cmd = app.add_subcommand("prepare", "Make the generated inputs (child of run)");
  prepare_cmd->add_option("--data", prepare.data_dir)->required();
  prepare_cmd->add_option("--work", prepare.work_dir)->required();
  prepare_cmd->add_option("--result", result_path)->required();
  add_input_options(*prepare_cmd, prepare);

  isoform_bench::Request request;
  std::vector<int> dims;
  std::vector<double> spacing;
  CLI::App* measure_cmd = app.add_subcommand("measure", "Measure one method on one input (child of run)");
  measure_cmd->add_option("--method", request.method)
      ->required()
      ->check(CLI::IsMember({"isoform", "isoform-raw", "volume-to-mesh", "flying-edges", "baseline"}));
  measure_cmd->add_option("--vdb", request.vdb);
  measure_cmd->add_option("--raw", request.raw.path);
  measure_cmd->add_option("--dims", dims)->delimiter(',')->expected(3);
  measure_cmd->add_option("--type", request.raw.type)->check(CLI::IsMember({"u16", "f32"}));
  measure_cmd->add_option("--spacing", spacing)->delimiter(',')->expected(3);
  measure_cmd->add_option("--iso", request.iso);
  measure_cmd->add_option("--reps", request.reps)->check(CLI::Range(1, 20));
  measure_cmd->add_option("--result", result_path)->required();

  CLI::App* cpu_cmd = app.add_subcommand(
      "cpu", "isoform and volumeToMesh in turn in one process on one .vdb: CPU and wall time per call");
  cpu_cmd->add_option("--vdb", request.vdb)->required();
  cpu_cmd->add_option("--iso", request.iso);
  cpu_cmd->add_option("--calls", request.reps, "Timed calls of each, after one untimed call of each")
      ->check(CLI::Range(1, 20));
  cpu_cmd->add_option("--result", result_path)->required();

  CLI11_PARSE(app, argc, argv);

  if (run_cmd->parsed()) return isoform_bench::run_all(run);
  if (prepare_cmd->parsed())
    return run_as_child(result_path, [&] { return isoform_bench::prepare_inputs(prepare); });

  for (size_t a = 0; a < dims.size() && a < 3; ++a) request.raw.dims[a] = dims[a];
  for (size_t a = 0; a < spacing.size() && a < 3; ++a) request.raw.spacing[a] = spacing[a];
  // Every method gets the same two worker threads (isoform also asks for
  // them through isoform_contour_options.threads).
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, isoform_bench::kThreads);
  if (cpu_cmd->parsed()) return run_as_child(result_path, [&] { return isoform_bench::measure_cpu_interleaved(request); });
  return run_as_child(result_path, [&]() -> Json {
    const std::string& m = request.method;
    if (m == "isoform" || m == "isoform-raw") return isoform_bench::measure_isoform(request);
    if (m == "volume-to-mesh") return isoform_bench::measure_volume_to_mesh(request);
    if (m == "baseline") return isoform_bench::measure_baseline();
#ifdef ISOFORM_BENCH_HAVE_VTK
    return isoform_bench::measure_flying_edges(request);
#else
    throw std::runtime_error("built without VTK: flying-edges is not available");
#endif
  });
}
