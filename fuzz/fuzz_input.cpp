// Shared pieces of the fuzz targets (see fuzz_input.h).
#include "fuzz_input.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace isoform::fuzz {

std::string as_file(const uint8_t* data, size_t size, const char* extension) {
  static const std::string folder =
      std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path().string();
  const std::string path = folder + "/isoform-fuzz-" + std::to_string(::getpid()) + extension;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

void exercise_volume(isoform_volume* volume) {
  const int grids = isoform_volume_grid_count(volume);
  for (int g = 0; g < grids; ++g) {
    isoform_grid_info info;
    if (isoform_volume_grid_info(volume, g, &info) != ISOFORM_OK) continue;
    if (!info.is_scalar || info.active_voxels > (1 << 16)) continue;
    isoform_contour_options options;
    isoform_contour_options_default(&options);
    options.threads = 1;
    isoform_mesh* mesh = nullptr;
    if (isoform_contour(volume, g, &options, nullptr, &mesh) == ISOFORM_OK) isoform_mesh_free(mesh);
  }
}

void exercise_mesh(isoform_mesh* mesh) {
  if (isoform_mesh_triangle_count(mesh) > 4096) return;
  isoform_curvature_options curvature;
  isoform_curvature_options_default(&curvature);
  curvature.threads = 1;
  if (isoform_curvature(mesh, &curvature, nullptr) != ISOFORM_OK) return;
  // Specks dropped after the curvature, so that its arrays are compacted too.
  isoform_part_filter filter;
  isoform_part_filter_default(&filter);
  filter.min_triangles = 2;
  filter.min_volume = 1e-12;
  if (isoform_mesh_filter_parts(mesh, &filter, nullptr) != ISOFORM_OK) return;
  isoform_reduce_options reduce;
  isoform_reduce_options_default(&reduce);
  reduce.keep_fraction = 0.5;
  if (isoform_reduce(mesh, &reduce, nullptr) != ISOFORM_OK) return;
  isoform_patch* patch = nullptr;
  if (isoform_patch_create(mesh, nullptr, &patch) != ISOFORM_OK) return;
  isoform_mesh* smooth = nullptr;
  if (isoform_patch_tessellate(patch, 2, nullptr, &smooth) == ISOFORM_OK) isoform_mesh_free(smooth);
  isoform_patch_free(patch);
}

void fuzz_volume_file(const uint8_t* data, size_t size, const char* extension,
                      const isoform_open_options* options) {
  isoform_volume* volume = nullptr;
  if (isoform_volume_open_with(as_file(data, size, extension).c_str(), options, &volume) != ISOFORM_OK) return;
  exercise_volume(volume);
  isoform_volume_free(volume);
}

void fuzz_mesh_file(const uint8_t* data, size_t size, const char* extension) {
  isoform_mesh* mesh = nullptr;
  if (isoform_mesh_load(as_file(data, size, extension).c_str(), &mesh) != ISOFORM_OK) return;
  exercise_mesh(mesh);
  isoform_mesh_free(mesh);
}

}  // namespace isoform::fuzz
