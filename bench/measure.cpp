// The `measure` children for isoform and OpenVDB's volumeToMesh: load the
// input, call the method once untimed, then `reps` timed calls; each call's
// output is freed before the next, so the peak is that of one call.
#include <fcntl.h>
#include <unistd.h>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <thread>

#include "bench.h"

namespace isoform_bench {

void check(isoform_status status, const std::string& what) {
  if (status != ISOFORM_OK)
    throw std::runtime_error(what + ": " + isoform_status_name(status) + ": " + isoform_last_error());
}

isoform_volume* open_raw_volume(const RawLayout& layout) {
  isoform_raw_options options;
  isoform_raw_options_default(&options);
  for (int a = 0; a < 3; ++a) {
    options.dims[a] = layout.dims[a];
    options.spacing[a] = layout.spacing[a];
  }
  options.scalar_type = layout.type == "u16" ? ISOFORM_U16 : ISOFORM_F32;
  isoform_volume* volume = nullptr;
  check(isoform_volume_open_raw(layout.path.c_str(), &options, &volume), "isoform_volume_open_raw");
  return volume;
}

long long peak_rss_kb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stoll(line.substr(6));
  throw std::runtime_error("no VmHWM in /proc/self/status");
}

Json timing_json(double load_ms, double first_ms, const std::vector<double>& timed_ms) {
  return Json{{"load_ms", load_ms},
              {"first_ms", first_ms},
              {"timed_ms", timed_ms},
              {"best_ms", *std::min_element(timed_ms.begin(), timed_ms.end())}};
}

void read_raw_into(const RawLayout& layout, char* out) {
  std::ifstream in(layout.path, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error(layout.path + ": cannot open");
  const size_t expected = layout.sample_count() * layout.sample_bytes();
  const auto size = size_t(in.tellg());
  if (size != expected)
    throw std::runtime_error(layout.path + ": " + std::to_string(size) + " bytes, the layout needs " +
                             std::to_string(expected));
  in.seekg(0);
  in.read(out, std::streamsize(size));
  if (!in) throw std::runtime_error(layout.path + ": read failed");
}

std::vector<char> read_raw_file(const RawLayout& layout) {
  std::vector<char> bytes(layout.sample_count() * layout.sample_bytes());
  read_raw_into(layout, bytes.data());
  return bytes;
}

namespace {

isoform_volume* open_isoform(const Request& request) {
  if (request.method == "isoform-raw") return open_raw_volume(request.raw);
  isoform_volume* volume = nullptr;
  check(isoform_volume_open(request.vdb.c_str(), &volume), "isoform_volume_open");
  return volume;
}

// Resident set size now, in kilobytes (one pread of /proc/self/statm).
class ResidentSet {
 public:
  ResidentSet()
      : fd_(open("/proc/self/statm", O_RDONLY | O_CLOEXEC)), page_kb_(sysconf(_SC_PAGESIZE) / 1024) {}
  ~ResidentSet() {
    if (fd_ >= 0) close(fd_);
  }
  long long kb() const {
    char text[128];
    const ssize_t n = fd_ >= 0 ? pread(fd_, text, sizeof text - 1, 0) : -1;
    if (n <= 0) return 0;
    text[n] = '\0';
    long long size = 0, resident = 0;
    return std::sscanf(text, "%lld %lld", &size, &resident) == 2 ? resident * page_kb_ : 0;
  }

 private:
  int fd_;
  long long page_kb_;
};

// Wall time and highest resident set seen in each isoform_stage during one
// isoform_contour call, read from the progress sink the library updates, as
// a UI timer would. The helper thread sleeps 1 ms between looks, so it
// takes next to no CPU from the two workers; the resident set it samples can
// miss a peak shorter than that (VmHWM does not).
class StageClock {
 public:
  StageClock() : thread_([this] { poll(); }) {}
  ~StageClock() {
    if (thread_.joinable()) stop();
  }
  isoform_progress* sink() { return &progress_; }
  Json stop() {
    stop_ = true;
    thread_.join();
    static const char* const names[] = {"idle", "load", "contour", "merge", "topology", "done"};
    Json out = Json::object();
    for (int s = ISOFORM_STAGE_LOAD; s <= ISOFORM_STAGE_TOPOLOGY; ++s)
      out[names[s]] = Json{{"ms", ms_[s]}, {"max_rss_kb", rss_kb_[s]}};
    return out;
  }

 private:
  void poll() {
    const ResidentSet rss;
    int stage = ISOFORM_STAGE_IDLE;
    Clock::time_point since = Clock::now();
    const auto account = [&] {
      const Clock::time_point now = Clock::now();
      ms_[stage] += ms_between(since, now);
      since = now;
    };
    while (!stop_) {
      const int seen = progress_.stage;
      if (seen != stage && seen >= ISOFORM_STAGE_IDLE && seen <= ISOFORM_STAGE_DONE) {
        account();
        stage = seen;
      }
      rss_kb_[stage] = std::max(rss_kb_[stage], rss.kb());
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    account();
  }

  isoform_progress progress_{};
  std::atomic<bool> stop_{false};
  double ms_[ISOFORM_STAGE_DONE + 1] = {};
  long long rss_kb_[ISOFORM_STAGE_DONE + 1] = {};
  std::thread thread_;
};

Json stats_json(const isoform_mesh_stats& s) {
  return Json{{"vertices", s.vertices},
              {"triangles", s.triangles},
              {"parts", s.parts},
              {"boundary_edges", s.boundary_edges},
              {"nonmanifold_edges", s.nonmanifold_edges},
              {"inconsistent_edges", s.inconsistent_edges},
              {"degenerate_triangles", s.degenerate_triangles},
              {"euler_characteristic", s.euler_characteristic},
              {"ambiguous_faces", s.ambiguous_faces},
              {"degenerate_saddles", s.degenerate_saddles},
              {"extra_points", s.extra_points},
              {"centroid_points", s.centroid_points}};
}

}  // namespace

Json measure_isoform(const Request& request) {
  if (isoform_version() != ISOFORM_VERSION)
    throw std::runtime_error("libisoform version " + std::to_string(isoform_version()) +
                             " does not match isoform.h (" + std::to_string(ISOFORM_VERSION) + ")");
  // What a user's program does before contouring: open, pick the grid, ask
  // for its facts (which reads the voxel data to find the value range).
  const Clock::time_point start = Clock::now();
  isoform_volume* volume = open_isoform(request);
  const int grid = isoform_volume_find_grid(volume, nullptr);
  if (grid < 0) throw std::runtime_error(std::string("isoform_volume_find_grid: ") + isoform_last_error());
  isoform_grid_info info;
  check(isoform_volume_grid_info(volume, grid, &info), "isoform_volume_grid_info");
  const double open_ms = ms_between(start, Clock::now());
  const long long peak_after_open = peak_rss_kb();

  isoform_contour_options options;
  isoform_contour_options_default(&options);
  options.auto_isovalue = 0;
  options.isovalue = request.iso;
  options.threads = kThreads;
  // The first call also loads the grid into the volume handle (isoform
  // reads voxel data when a grid is first used), so it is reported apart.
  // Every call gets a progress sink, as the CLI passes one. The stages are
  // timed, and the resident set sampled every ms, by a thread of the
  // bench's own (StageClock) in the first call and in one more call after
  // the timed ones, never in a timed call: volumeToMesh's calls share the
  // two cores with no such thread, and neither do isoform's timed ones.
  const auto call_with = [&](isoform_progress* sink, isoform_mesh_stats& out) {
    isoform_mesh* mesh = nullptr;
    const Clock::time_point t = Clock::now();
    check(isoform_contour(volume, grid, &options, sink, &mesh), "isoform_contour");
    const double ms = ms_between(t, Clock::now());
    check(isoform_mesh_stats_get(mesh, &out), "isoform_mesh_stats_get");
    isoform_mesh_free(mesh);
    return ms;
  };
  const auto staged_call = [&](double& ms, isoform_mesh_stats& out) {
    StageClock clock;
    ms = call_with(clock.sink(), out);
    return clock.stop();
  };
  isoform_mesh_stats stats{};
  double first_ms = 0.0, staged_ms = 0.0;
  const Json first_stages = staged_call(first_ms, stats);
  std::vector<double> timed;
  for (int call = 1; call <= request.reps; ++call) {
    isoform_progress sink{};
    timed.push_back(call_with(&sink, stats));
  }
  const Json stages = staged_call(staged_ms, stats);
  isoform_volume_free(volume);

  Json out = timing_json(open_ms, first_ms, timed);
  out["load_note"] = "open + find_grid + grid_info; the first contour call reads the grid again";
  out["first_stages"] = first_stages;
  out["stages"] = stages;
  out["staged_ms"] = staged_ms;
  out["active_voxels"] = info.active_voxels;
  out["value_range"] = {info.value_min, info.value_max};
  out["mesh"] = stats_json(stats);
  out["peak_after_load_kb"] = peak_after_open;
  out["peak_kb"] = peak_rss_kb();
  return out;
}

Json measure_volume_to_mesh(const Request& request) {
  openvdb::initialize();
  const Clock::time_point start = Clock::now();
  openvdb::FloatGrid::Ptr grid;
  {
    openvdb::io::File file(request.vdb);
    // Without delayed loading, so that no file reading hides in the first call.
    file.open(false);
    const openvdb::io::File::NameIterator first = file.beginName();
    if (first == file.endName()) throw std::runtime_error(request.vdb + ": no grids");
    grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(first.gridName()));
    if (!grid) throw std::runtime_error(request.vdb + ": the first grid is not a float grid");
  }
  const double load_ms = ms_between(start, Clock::now());
  const long long peak_after_load = peak_rss_kb();

  double first_ms = 0.0;
  std::vector<double> timed;
  size_t points = 0, triangles = 0, quads = 0;
  for (int call = 0; call <= request.reps; ++call) {
    std::vector<openvdb::Vec3s> p;
    std::vector<openvdb::Vec3I> t3;
    std::vector<openvdb::Vec4I> q4;
    const Clock::time_point t = Clock::now();
    openvdb::tools::volumeToMesh(*grid, p, t3, q4, request.iso, /*adaptivity=*/0.0);
    const double ms = ms_between(t, Clock::now());
    if (call == 0)
      first_ms = ms;
    else
      timed.push_back(ms);
    points = p.size();
    triangles = t3.size();
    quads = q4.size();
  }

  Json out = timing_json(load_ms, first_ms, timed);
  out["load_note"] = "io::File read of the first grid, not delayed";
  out["active_voxels"] = grid->activeVoxelCount();
  out["mesh"] = Json{{"points", points}, {"triangles", triangles}, {"quads", quads}};
  out["peak_after_load_kb"] = peak_after_load;
  out["peak_kb"] = peak_rss_kb();
  return out;
}

Json measure_baseline() { return Json{{"peak_kb", peak_rss_kb()}}; }

}  // namespace isoform_bench
