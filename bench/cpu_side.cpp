// The `cpu` sub-command: isoform_contour and volumeToMesh called in turn
// (A B A B ...) in one process on the same file, each call's process CPU
// time (user + system, all threads) and wall time recorded. Load moves CPU
// time far less than wall time on a shared machine, and interleaving makes
// drift hit both methods alike.
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <time.h>

#include <algorithm>
#include <cstdio>

#include "bench.h"

namespace isoform_bench {
namespace {

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Sample {
  double cpu_ms, wall_ms;
};

template <class F>
Sample timed(F&& f) {
  const double c = cpu_seconds();
  const Clock::time_point w = Clock::now();
  f();
  return {1e3 * (cpu_seconds() - c), ms_between(w, Clock::now())};
}

Json samples_json(const std::vector<Sample>& s) {
  Json cpu = Json::array(), wall = Json::array();
  double best_cpu = s.front().cpu_ms, best_wall = s.front().wall_ms;
  for (const Sample& x : s) {
    cpu.push_back(x.cpu_ms);
    wall.push_back(x.wall_ms);
    best_cpu = std::min(best_cpu, x.cpu_ms);
    best_wall = std::min(best_wall, x.wall_ms);
  }
  return Json{{"cpu_ms", cpu}, {"wall_ms", wall}, {"best_cpu_ms", best_cpu}, {"best_wall_ms", best_wall}};
}

}  // namespace

Json measure_cpu_interleaved(const Request& request) {
  openvdb::initialize();
  isoform_volume* volume = nullptr;
  check(isoform_volume_open(request.vdb.c_str(), &volume), "isoform_volume_open");
  const int grid = isoform_volume_find_grid(volume, nullptr);
  if (grid < 0) throw std::runtime_error(std::string("isoform_volume_find_grid: ") + isoform_last_error());
  openvdb::FloatGrid::Ptr vdb;
  {
    openvdb::io::File file(request.vdb);
    file.open(false);
    vdb = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(file.beginName().gridName()));
    if (!vdb) throw std::runtime_error(request.vdb + ": the first grid is not a float grid");
  }
  isoform_contour_options options;
  isoform_contour_options_default(&options);
  options.auto_isovalue = 0;
  options.isovalue = request.iso;
  options.threads = kThreads;
  std::vector<Sample> iso, vtm;
  isoform_mesh_stats stats{};
  size_t quads = 0;
  // Call 0 of each is untimed (isoform reads the grid into the handle then).
  for (int call = 0; call <= request.reps; ++call) {
    isoform_mesh* mesh = nullptr;
    const Sample a = timed([&] { check(isoform_contour(volume, grid, &options, nullptr, &mesh), "isoform_contour"); });
    check(isoform_mesh_stats_get(mesh, &stats), "isoform_mesh_stats_get");
    isoform_mesh_free(mesh);
    std::vector<openvdb::Vec3s> p;
    std::vector<openvdb::Vec3I> t3;
    std::vector<openvdb::Vec4I> q4;
    const Sample b = timed([&] { openvdb::tools::volumeToMesh(*vdb, p, t3, q4, request.iso, 0.0); });
    quads = q4.size();
    if (call > 0) {
      iso.push_back(a);
      vtm.push_back(b);
    }
    std::fprintf(stderr, "call %d: isoform %.1f ms cpu %.1f ms wall, volumeToMesh %.1f ms cpu %.1f ms wall\n", call,
                 a.cpu_ms, a.wall_ms, b.cpu_ms, b.wall_ms);
  }
  isoform_volume_free(volume);
  Json out{{"isoform", samples_json(iso)}, {"volume_to_mesh", samples_json(vtm)}};
  out["cpu_ratio"] = out["volume_to_mesh"]["best_cpu_ms"].get<double>() / out["isoform"]["best_cpu_ms"].get<double>();
  out["wall_ratio"] =
      out["volume_to_mesh"]["best_wall_ms"].get<double>() / out["isoform"]["best_wall_ms"].get<double>();
  out["isoform_triangles"] = stats.triangles;
  out["isoform_vertices"] = stats.vertices;
  out["volume_to_mesh_quads"] = quads;
  return out;
}

}  // namespace isoform_bench
