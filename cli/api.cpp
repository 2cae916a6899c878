// Throwing wrappers over the C API calls that several commands share.
#include "cli.h"

namespace isoform::cli {

void check(isoform_status status) {
  if (status != ISOFORM_OK) {
    const int code = status == ISOFORM_ERR_CANCELLED ? kInterruptedExitCode : 1;
    throw Failure(isoform_last_error(), code);
  }
}

namespace {
int volume_index = -1;  // --volume, for every volume file the command opens
}  // namespace

void set_volume_index(int index) { volume_index = index; }

VolumePtr open_volume(const std::string& path) {
  isoform_open_options options;
  isoform_open_options_default(&options);
  options.volume = volume_index;
  isoform_volume* volume = nullptr;
  check(isoform_volume_open_with(path.c_str(), &options, &volume));
  return VolumePtr(volume);
}

isoform_grid_info grid_info(const isoform_volume* volume, int index) {
  isoform_grid_info info{};
  check(isoform_volume_grid_info(volume, index, &info));
  return info;
}

int find_grid(const isoform_volume* volume, const std::string& name) {
  const int index = isoform_volume_find_grid(volume, name.c_str());
  if (index < 0) throw Failure(isoform_last_error());
  return index;
}

isoform_mesh_stats mesh_stats(const isoform_mesh* mesh) {
  isoform_mesh_stats stats{};
  check(isoform_mesh_stats_get(mesh, &stats));
  return stats;
}

}  // namespace isoform::cli
