// The `prepare` child: makes the inputs that are not files in ../shared/data.
// - a narrow-band level-set sphere from openvdb::tools::createLevelSetSphere;
// - headsq as a sparse VDB, converted by isoform's own C API (what
//   `isoform convert` gives users);
// - headsq resampled trilinearly to isotropic 0.8 spacing, as a raw float
//   scan (for Flying Edges and isoform's dense path) and as a VDB, so the
//   dense comparison runs on something bigger than 64x64x93.
// Each is written to a temporary name and renamed, and kept for later runs.
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "bench.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "raw scans are written little-endian as they are");

namespace isoform_bench {

namespace fs = std::filesystem;

namespace {

constexpr double kResampleSpacing = 0.8;

void make_sphere(const std::string& path, int radius, Json& report) {
  openvdb::initialize();
  const Clock::time_point start = Clock::now();
  openvdb::FloatGrid::Ptr grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
      float(radius), openvdb::Vec3f(0, 0, 0), /*voxelSize=*/1.0f, /*halfWidth=*/3.0f);
  grid->setName("ls_sphere");
  const std::string temporary = path + ".tmp";
  openvdb::io::File file(temporary);
  // No zip or blosc on the values: loading is not what is measured, and
  // fast loading keeps the run short.
  file.setCompression(openvdb::io::COMPRESS_ACTIVE_MASK);
  file.write({grid});
  file.close();
  fs::rename(temporary, path);
  report["sphere"] = Json{{"path", path},
                          {"radius_voxels", radius},
                          {"active_voxels", grid->activeVoxelCount()},
                          {"leaves", grid->tree().leafCount()},
                          {"made_ms", ms_between(start, Clock::now())}};
}

void raw_to_vdb(const RawLayout& layout, const std::string& path) {
  isoform_volume* volume = open_raw_volume(layout);
  const isoform_status saved = isoform_volume_save_vdb(volume, path.c_str());
  isoform_volume_free(volume);
  check(saved, "isoform_volume_save_vdb");
}

// Trilinear interpolation of the u16 scan at the sample points of the finer,
// isotropic grid (same origin, same extent up to one fine sample).
void resample(const RawLayout& from, const RawLayout& to) {
  const std::vector<char> bytes = read_raw_file(from);
  const auto sample = [&](int i, int j, int k) {
    const size_t at = (size_t(k) * size_t(from.dims[1]) + size_t(j)) * size_t(from.dims[0]) + size_t(i);
    uint16_t v;
    std::memcpy(&v, bytes.data() + 2 * at, 2);
    return float(v);
  };
  // Source position of each fine sample along one axis: lower index and weight.
  std::array<std::vector<std::pair<int, float>>, 3> axis;
  for (int a = 0; a < 3; ++a)
    for (int n = 0; n < to.dims[a]; ++n) {
      const double x = n * to.spacing[a] / from.spacing[a];
      const int lower = std::min(int(x), from.dims[a] - 2);
      axis[a].emplace_back(lower, float(x - lower));
    }
  const auto lerp = [](float a, float b, float w) { return a + (b - a) * w; };
  std::vector<float> out(to.sample_count());
  size_t at = 0;
  for (const auto& [k, wz] : axis[2])
    for (const auto& [j, wy] : axis[1])
      for (const auto& [i, wx] : axis[0]) {
        const float y0 = lerp(lerp(sample(i, j, k), sample(i + 1, j, k), wx),
                              lerp(sample(i, j + 1, k), sample(i + 1, j + 1, k), wx), wy);
        const float y1 = lerp(lerp(sample(i, j, k + 1), sample(i + 1, j, k + 1), wx),
                              lerp(sample(i, j + 1, k + 1), sample(i + 1, j + 1, k + 1), wx), wy);
        out[at++] = lerp(y0, y1, wz);
      }
  const std::string temporary = to.path + ".tmp";
  {
    std::ofstream file(temporary, std::ios::binary);
    file.write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size() * sizeof(float)));
    if (!file) throw std::runtime_error(temporary + ": write failed");
  }
  fs::rename(temporary, to.path);
}

}  // namespace

std::string sphere_path(const std::string& work_dir, int radius) {
  return work_dir + "/sphere_r" + std::to_string(radius) + ".vdb";
}

std::string headsq_vdb_path(const std::string& work_dir) { return work_dir + "/headsq.vdb"; }

RawLayout headsq_layout(const std::string& data_dir) {
  RawLayout layout;
  layout.path = data_dir + "/headsq_64x64x93_u16le.raw";
  layout.dims = {64, 64, 93};
  layout.type = "u16";
  layout.spacing = {3.2, 3.2, 1.5};
  return layout;
}

RawLayout resampled_layout(const std::string& work_dir) {
  const RawLayout from = headsq_layout("");
  RawLayout layout;
  layout.type = "f32";
  for (int a = 0; a < 3; ++a) {
    layout.dims[a] = int(std::floor((from.dims[a] - 1) * from.spacing[a] / kResampleSpacing + 1e-9)) + 1;
    layout.spacing[a] = kResampleSpacing;
  }
  layout.path = work_dir + "/headsq_resampled_" + std::to_string(layout.dims[0]) + "x" +
                std::to_string(layout.dims[1]) + "x" + std::to_string(layout.dims[2]) + "_f32le.raw";
  return layout;
}

std::string resampled_vdb_path(const std::string& work_dir) {
  const std::string raw = resampled_layout(work_dir).path;
  return raw.substr(0, raw.size() - std::string("_f32le.raw").size()) + ".vdb";
}

Json prepare_inputs(const PrepareOptions& options) {
  fs::create_directories(options.work_dir);
  Json report = Json::object();
  if (options.sphere) {
    const std::string path = sphere_path(options.work_dir, options.sphere_radius);
    if (!fs::exists(path)) make_sphere(path, options.sphere_radius, report);
  }
  const std::string headsq = headsq_vdb_path(options.work_dir);
  if (!fs::exists(headsq)) {
    raw_to_vdb(headsq_layout(options.data_dir), headsq);
    report["headsq_vdb"] = headsq;
  }
  if (options.resample) {
    const RawLayout fine = resampled_layout(options.work_dir);
    if (!fs::exists(fine.path)) {
      resample(headsq_layout(options.data_dir), fine);
      report["resampled_raw"] = fine.path;
    }
    const std::string vdb = resampled_vdb_path(options.work_dir);
    if (!fs::exists(vdb)) {
      raw_to_vdb(fine, vdb);
      report["resampled_vdb"] = vdb;
    }
  }
  return report;
}

}  // namespace isoform_bench
