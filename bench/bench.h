// isoform_bench: isoform's contour against OpenVDB's volumeToMesh and VTK's
// Flying Edges, on the same inputs, in one run.
//
// The driver (`run`) starts this same executable once per (method, input)
// with the `measure` sub-command, so that each method's peak memory is its
// own process's high-water mark, loading included. Inputs that do not exist
// as files yet are made by the `prepare` sub-command, also in a child, so the
// driver stays small.
#pragma once

#include <array>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "isoform.h"

namespace isoform_bench {

using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

// The bench's targets are stated for two worker threads (bench/README.md:
// throughput at 2 threads).
constexpr int kThreads = 2;

inline double ms_between(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

// A headerless dense scan: x fastest, little-endian samples.
struct RawLayout {
  std::string path;
  std::array<int, 3> dims{0, 0, 0};
  std::string type;  // "u16" or "f32"
  std::array<double, 3> spacing{1, 1, 1};

  size_t sample_count() const { return size_t(dims[0]) * size_t(dims[1]) * size_t(dims[2]); }
  size_t sample_bytes() const { return type == "u16" ? 2 : 4; }
};

// What one `measure` child is asked to do.
struct Request {
  // "isoform" (a .vdb through isoform_volume_open), "isoform-raw" (a raw scan
  // through isoform_volume_open_raw), "volume-to-mesh", "flying-edges" (raw),
  // or "baseline" (load nothing: the cost of the process itself).
  std::string method;
  std::string vdb;  // for "isoform" and "volume-to-mesh"
  RawLayout raw;    // for "isoform-raw" and "flying-edges"
  double iso = 0.0;
  int reps = 3;  // timed calls, after one untimed first call
};

// Throws std::runtime_error naming the call, the status and isoform's message
// unless status is ISOFORM_OK.
void check(isoform_status status, const std::string& what);

// Opens a raw scan through isoform's C API (isoform_volume_open_raw); the
// caller frees the volume.
isoform_volume* open_raw_volume(const RawLayout& layout);

// The process's peak resident set (VmHWM) in kilobytes. Read in the child
// itself: on Linux a fork+exec child's ru_maxrss also counts the parent's
// resident pages at fork time, so getrusage in the parent would overstate it.
long long peak_rss_kb();

// Each returns the result object documented in README.md (times in ms,
// counts, "peak_kb"); failures throw std::runtime_error with a message.
Json measure_isoform(const Request& request);
Json measure_volume_to_mesh(const Request& request);
Json measure_baseline();
// The `cpu` sub-command (cpu_side.cpp): isoform_contour and volumeToMesh in
// turn in one process, CPU and wall time of every call, request.reps each.
Json measure_cpu_interleaved(const Request& request);
#ifdef ISOFORM_BENCH_HAVE_VTK
Json measure_flying_edges(const Request& request);
#endif

// Times: first call, each timed call, and the best of them.
Json timing_json(double load_ms, double first_ms, const std::vector<double>& timed_ms);

// Reads a whole raw scan, checking its size against the layout, into out
// (sample_count() * sample_bytes() bytes) or into a new buffer.
void read_raw_into(const RawLayout& layout, char* out);
std::vector<char> read_raw_file(const RawLayout& layout);

// Inputs made by `prepare` (cached in the work folder, remade if missing).
struct PrepareOptions {
  std::string data_dir;     // the real test data (../shared/data)
  std::string work_dir;     // generated inputs go here
  int sphere_radius = 814;  // voxels; about 50M active voxels at half width 3
  bool sphere = true;
  bool resample = true;
};
Json prepare_inputs(const PrepareOptions& options);

// File names prepare_inputs writes in the work folder.
std::string sphere_path(const std::string& work_dir, int radius);
std::string headsq_vdb_path(const std::string& work_dir);
RawLayout headsq_layout(const std::string& data_dir);
RawLayout resampled_layout(const std::string& work_dir);
std::string resampled_vdb_path(const std::string& work_dir);

// NOTE: the defaults take the best of 30 calls per method and input (reps
// times rounds): on a shared machine a single call's time moves with the
// host's load, and the best of fewer calls left the ratios between the
// methods differing from one run to the next.
struct RunOptions {
  PrepareOptions prepare;
  std::string json_path;
  int reps = 10;
  int rounds = 3;  // each method runs once per round, in turn
};
// Runs every (method, input) in its own child, prints the tables, writes the
// JSON report. Returns the process exit code.
int run_all(const RunOptions& options);

}  // namespace isoform_bench
