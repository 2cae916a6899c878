// The C API's volume calls that need no file format: grid facts, lookup,
// dense caller arrays and the phantom. Opening and saving files is in vdbio.
#include <cstring>

#include "../errors.h"
#include "../phantom.h"
#include "handles.h"

using isoform::capi::fail;
using isoform::capi::guarded;

std::shared_ptr<const isoform::ScalarGrid> isoform_volume::grid(int index) const {
  std::lock_guard<std::mutex> lock(mutex);
  auto it = loaded.find(index);
  if (it != loaded.end()) return it->second;
  auto g = file->load(index);
  loaded[index] = g;
  return g;
}

namespace {

void copy_facts(const isoform::GridFacts& f, isoform_grid_info* out) {
  std::memset(out, 0, sizeof(*out));
  std::strncpy(out->name, f.name.c_str(), sizeof(out->name) - 1);
  std::strncpy(out->value_type, f.value_type.c_str(), sizeof(out->value_type) - 1);
  out->grid_class = int(f.grid_class);
  out->is_scalar = f.is_scalar;
  out->value_min = f.value_min;
  out->value_max = f.value_max;
  out->background = f.background;
  out->active_voxels = f.active_voxels;
  const isoform::Vec3d vs = f.index_to_world.voxel_size();
  for (int a = 0; a < 3; ++a) {
    out->bbox_min[a] = f.bbox_min[a];
    out->bbox_max[a] = f.bbox_max[a];
    out->voxel_size[a] = vs[a];
    for (int c = 0; c < 4; ++c) out->transform[4 * a + c] = f.index_to_world.m[a][c];
  }
  out->transform[15] = 1.0;
  std::strncpy(out->space, f.space.c_str(), sizeof(out->space) - 1);
  std::strncpy(out->unit, f.unit.c_str(), sizeof(out->unit) - 1);
}

std::string source_name(const isoform_volume* v) {
  const std::string p = v->file->path();
  return p.empty() ? std::string("volume") : p;
}

}  // namespace

extern "C" {

void isoform_volume_free(isoform_volume* volume) { delete volume; }

int isoform_volume_grid_count(const isoform_volume* volume) {
  return volume ? volume->file->grid_count() : 0;
}

isoform_status isoform_volume_grid_info(const isoform_volume* volume, int index, isoform_grid_info* out) {
  return guarded([&] {
    if (!volume || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_volume_grid_info: NULL argument");
    if (index < 0 || index >= volume->file->grid_count())
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, source_name(volume) + ": grid index " + std::to_string(index) +
                                                    " out of range (" + std::to_string(volume->file->grid_count()) +
                                                    " grids)");
    copy_facts(volume->file->facts(index), out);
    return ISOFORM_OK;
  });
}

int isoform_volume_find_grid(const isoform_volume* volume, const char* name) {
  int found = -1;
  const isoform_status st = guarded([&] {
    if (!volume) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_volume_find_grid: NULL volume");
    const int n = volume->file->grid_count();
    const bool first_scalar = !name || !*name;
    std::string names;
    for (int i = 0; i < n && found < 0; ++i) {
      const isoform::GridFacts f = volume->file->facts(i);
      if (first_scalar ? f.is_scalar : f.name == name) found = i;
      names += (names.empty() ? "" : ", ") + ("'" + f.name + "'");
    }
    if (found >= 0) return ISOFORM_OK;
    if (first_scalar) return fail(ISOFORM_ERR_UNSUPPORTED, source_name(volume) + ": no scalar grid (grids: " + names + ")");
    return fail(ISOFORM_ERR_INVALID_ARGUMENT, source_name(volume) + ": no grid named '" + name +
                                                  "'; grids: " + (names.empty() ? "none" : names));
  });
  return st == ISOFORM_OK ? found : -1;
}

isoform_status isoform_volume_from_dense(const float* values, int nx, int ny, int nz, const double spacing[3],
                                         const double origin[3], const char* name, int grid_class,
                                         isoform_volume** out) {
  return guarded([&] {
    if (!values || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_volume_from_dense: NULL argument");
    *out = nullptr;
    if (nx < 2 || ny < 2 || nz < 2)
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_volume_from_dense: each dimension needs 2 or more samples");
    if (grid_class < 0 || grid_class > 2)
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_volume_from_dense: unknown grid class");
    const isoform::Vec3d s = spacing ? isoform::Vec3d{spacing[0], spacing[1], spacing[2]} : isoform::Vec3d{1, 1, 1};
    const isoform::Vec3d o = origin ? isoform::Vec3d{origin[0], origin[1], origin[2]} : isoform::Vec3d{0, 0, 0};
    std::vector<float> v(values, values + size_t(nx) * size_t(ny) * size_t(nz));
    auto file = std::make_shared<isoform::DenseVolume>(name && *name ? name : "density",
                                                       isoform::GridClass(grid_class), std::move(v),
                                                       isoform::Index3{nx, ny, nz},
                                                       isoform::Affine::scale_translate(s, o));
    *out = new isoform_volume();
    (*out)->file = std::move(file);
    return ISOFORM_OK;
  });
}

isoform_status isoform_volume_phantom(int n, isoform_volume** out) {
  return guarded([&] {
    if (!out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_volume_phantom: NULL argument");
    *out = nullptr;
    auto file = isoform::make_phantom(n);
    *out = new isoform_volume();
    (*out)->file = std::move(file);
    return ISOFORM_OK;
  });
}

}  // extern "C"
