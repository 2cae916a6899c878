// Dense arrays as bricks and as a one-grid VolumeFile.
#include <algorithm>

#include "errors.h"
#include "volume.h"

namespace isoform {

DenseBricks::DenseBricks(std::shared_ptr<const std::vector<float>> values, const Index3& dims,
                         int brick_cells)
    : values_(std::move(values)), dims_(dims), brick_cells_(brick_cells) {
  // Bricks tile the samples [0, dims): each owns the cells whose lower
  // corner it holds; cells reaching past the array are left out in fill().
  for (int a = 0; a < 3; ++a) brick_counts_[a] = (dims_[a] + brick_cells_ - 1) / brick_cells_;
}

size_t DenseBricks::brick_count() const {
  return size_t(brick_counts_[0]) * size_t(brick_counts_[1]) * size_t(brick_counts_[2]);
}

void DenseBricks::fill(size_t index, Brick& out) const {
  const Index3 b{int(index % size_t(brick_counts_[0])),
                 int(index / size_t(brick_counts_[0]) % size_t(brick_counts_[1])),
                 int(index / (size_t(brick_counts_[0]) * size_t(brick_counts_[1])))};
  Index3 origin, cells;
  for (int a = 0; a < 3; ++a) {
    origin[a] = b[a] * brick_cells_;
    cells[a] = std::min(brick_cells_, dims_[a] - origin[a]);
  }
  out.resize(origin, cells, true);
  const Index3 d = out.dims();
  const std::vector<float>& v = *values_;
  for (int k = -1; k < d[2] - 1; ++k) {
    const int gz = origin[2] + k;
    for (int j = -1; j < d[1] - 1; ++j) {
      const int gy = origin[1] + j;
      for (int i = -1; i < d[0] - 1; ++i) {
        const int gx = origin[0] + i;
        const size_t at = out.at(i, j, k);
        const bool inside = gx >= 0 && gy >= 0 && gz >= 0 && gx < dims_[0] && gy < dims_[1] &&
                            gz < dims_[2];
        out.defined[at] = inside;
        out.samples[at] =
            inside ? v[(size_t(gz) * size_t(dims_[1]) + size_t(gy)) * size_t(dims_[0]) + size_t(gx)]
                   : 0.0f;
      }
    }
  }
}

DenseVolume::DenseVolume(std::string name, GridClass grid_class, std::vector<float> values,
                         const Index3& dims, const Affine& index_to_world, std::string path)
    : path_(std::move(path)), dims_(dims) {
  const size_t n = size_t(dims[0]) * size_t(dims[1]) * size_t(dims[2]);
  if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1 || values.size() != n)
    throw InvalidArgument((path_.empty() ? name : path_) + ": dense array of " +
                          std::to_string(values.size()) + " samples does not match dims " +
                          std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
                          std::to_string(dims[2]));
  check_finite(values, path_.empty() ? name : path_);
  grid_ = std::make_shared<ScalarGrid>();
  grid_->name = std::move(name);
  grid_->grid_class = grid_class;
  grid_->index_to_world = index_to_world;
  grid_->background = 0.0;
  const auto mm = std::minmax_element(values.begin(), values.end());
  grid_->value_min = *mm.first;
  grid_->value_max = *mm.second;
  active_ = (long long)n;
  grid_->bricks = std::make_shared<DenseBricks>(
      std::make_shared<const std::vector<float>>(std::move(values)), dims);
}

GridFacts DenseVolume::facts(int i) const {
  if (i != 0) throw InvalidArgument("grid index " + std::to_string(i) + " out of range");
  GridFacts f;
  f.name = grid_->name;
  f.value_type = "float";
  f.grid_class = grid_->grid_class;
  f.is_scalar = true;
  f.value_min = grid_->value_min;
  f.value_max = grid_->value_max;
  f.background = grid_->background;
  f.active_voxels = active_;
  f.bbox_min = {0, 0, 0};
  f.bbox_max = {dims_[0] - 1, dims_[1] - 1, dims_[2] - 1};
  f.index_to_world = grid_->index_to_world;
  f.space = space_;
  f.unit = unit_;
  return f;
}

void DenseVolume::set_frame(std::string space, std::string unit) {
  space_ = std::move(space);
  unit_ = std::move(unit);
}

std::shared_ptr<const ScalarGrid> DenseVolume::load(int i) const {
  if (i != 0) throw InvalidArgument("grid index " + std::to_string(i) + " out of range");
  return grid_;
}

}  // namespace isoform
