// An OpenVDB file as a VolumeFile: grid metadata at open, voxel data on
// demand, scalar grids converted to float and checked before contouring.
#include "vdb_file.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <vector>

#include "active_bricks.h"
#include "input_file.h"
#include "leaf_bricks.h"
#include "libcore/errors.h"
#include "vdb_convert.h"
#include "vdb_errors.h"
#include "vdb_layout.h"

namespace isoform::vdbio {

namespace {

using ScalarGrids = openvdb::TypeList<openvdb::FloatGrid, openvdb::DoubleGrid, openvdb::Int32Grid,
                                      openvdb::Int64Grid>;

// One pass over every value a tree stores: the range of the active ones,
// and the first place (voxel or tile origin) holding NaN or Inf.
struct ValueScan {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  bool bad = false;
  double bad_value = 0.0;
  openvdb::Coord bad_at;

  // where() gives the place of v; it is asked only for the first bad value.
  template <class Where>
  void add(double v, bool active, Where&& where) {
    if (!std::isfinite(v)) {
      if (!bad) {
        bad = true;
        bad_value = v;
        bad_at = where();
      }
    } else if (active) {
      min = std::min(min, v);
      max = std::max(max, v);
    }
  }
  // The scan of values that come after this one's.
  void join(const ValueScan& later) {
    min = std::min(min, later.min);
    max = std::max(max, later.max);
    if (!bad && later.bad) {
      bad = true;
      bad_value = later.bad_value;
      bad_at = later.bad_at;
    }
  }
};

template <class TreeT>
ValueScan scan_values(const TreeT& tree) {
  using LeafT = typename TreeT::LeafNodeType;
  // NOTE: the leaves are scanned in parallel, in ranges joined in leaf
  // order: the range is exact whatever the order (the leftmost of equal
  // extremes is kept, as the serial scan keeps it), and the first bad
  // value of the leftmost range that has one is the serial scan's first.
  std::vector<const LeafT*> leaves;
  leaves.reserve(tree.leafCount());
  for (auto leaf = tree.cbeginLeaf(); leaf; ++leaf) leaves.push_back(&*leaf);
  ValueScan scan = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, leaves.size(), 256), ValueScan{},
      [&](const tbb::blocked_range<size_t>& range, ValueScan part) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
          const LeafT& leaf = *leaves[i];
          const auto* values = leaf.buffer().data();
          const auto& mask = leaf.getValueMask();
          for (openvdb::Index n = 0; n < LeafT::SIZE; ++n)
            part.add(double(values[n]), mask.isOn(n), [&] { return leaf.offsetToGlobalCoord(n); });
        }
        return part;
      },
      [](ValueScan left, const ValueScan& right) {
        left.join(right);
        return left;
      });
  auto tile = tree.cbeginValueAll();
  tile.setMaxDepth(TreeT::ValueAllCIter::LEAF_DEPTH - 1);  // tiles only, no voxels
  for (; tile; ++tile) scan.add(double(*tile), tile.isValueOn(), [&] { return tile.getCoord(); });
  return scan;
}

// Bricks carry every stored value, active or not, and the background.
void require_finite(const ValueScan& scan, double background, const std::string& what) {
  const auto kind = [](double v) { return std::isnan(v) ? std::string("a NaN") : "an infinite"; };
  if (scan.bad)
    throw FormatError(what + " has " + kind(scan.bad_value) + " value at voxel (" +
                      std::to_string(scan.bad_at.x()) + ", " + std::to_string(scan.bad_at.y()) +
                      ", " + std::to_string(scan.bad_at.z()) + "); isoform needs finite values");
  if (!std::isfinite(background))
    throw FormatError(what + " has " + kind(background) +
                      " background; isoform needs finite values");
}

// A frame or unit the grid's metadata names, if it is one isoform knows.
std::string frame_metadata(const openvdb::GridBase& grid, const char* name,
                           std::initializer_list<const char*> known) {
  const auto value = grid.getMetadata<openvdb::StringMetadata>(name);
  if (!value) return "";
  for (const char* k : known)
    if (value->value() == k) return k;
  return "";
}

// Value range and background of a scalar grid, in its own value type.
void add_scalar_facts(const openvdb::GridBase& grid, const std::string& what, GridFacts& facts) {
  grid.apply<ScalarGrids>([&](const auto& typed) {
    const ValueScan scan = scan_values(typed.tree());
    require_finite(scan, double(typed.background()), what);
    facts.background = double(typed.background());
    if (facts.active_voxels > 0) {
      facts.value_min = scan.min;
      facts.value_max = scan.max;
    }
  });
}

}  // namespace

VdbFile::VdbFile(std::string path) : path_(std::move(path)), layout_(check_vdb_layout(path_)) {
  for (const VdbGridEntry& g : layout_.grids) names_.push_back(g.unique_name);
  reading_vdb(path_, [this] {
    openvdb::io::File file(path_);
    file.open(false);
    for (const std::string& name : names_) grids_.push_back(file.readGridMetadata(name));
  });
  facts_.resize(grids_.size());
}

std::string VdbFile::describe(int i) const {
  return path_ + ": grid '" + grids_[size_t(i)]->getName() + "'";
}

openvdb::GridBase::Ptr VdbFile::read_grid(int i) const {
  if (i < 0 || i >= grid_count())
    throw InvalidArgument(path_ + ": grid index " + std::to_string(i) +
                          " out of range (the file has " + std::to_string(grid_count()) +
                          " grids)");
  // The file may have been cut short or replaced since it was opened; what
  // OpenVDB reads next is walked first, as it is now.
  const VdbLayout now = check_vdb_layout(path_);
  if (now.file_size != layout_.file_size || now.grids != layout_.grids)
    throw FormatError(path_ + ": the file changed after it was opened; open it again");
  check_vdb_grid(path_, now, i, memory_budget());
  return reading_vdb(path_, [&] {
    openvdb::io::File file(path_);
    // Without delayed loading every value is read now, not on first access
    // from a worker thread, where a read error could not be reported.
    file.open(false);
    return file.readGrid(names_[size_t(i)]);
  });
}

GridFacts VdbFile::facts(int i) const {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (i >= 0 && i < grid_count() && facts_[size_t(i)]) return *facts_[size_t(i)];
  }
  const openvdb::GridBase::Ptr grid = read_grid(i);
  GridFacts facts;
  facts.name = grid->getName();
  facts.value_type = value_type_name(*grid);
  facts.grid_class = to_grid_class(grid->getGridClass());
  facts.is_scalar = is_scalar_grid(*grid);
  facts.index_to_world = to_affine(grid->transform(), describe(i));
  facts.active_voxels = (long long)grid->activeVoxelCount();
  if (facts.active_voxels > 0) {
    const openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
    facts.bbox_min = {box.min().x(), box.min().y(), box.min().z()};
    facts.bbox_max = {box.max().x(), box.max().y(), box.max().z()};
  }
  if (facts.is_scalar) add_scalar_facts(*grid, describe(i), facts);
  facts.space = frame_metadata(*grid, kSpaceMetadata, {"RAS", "LPS", "LAS"});
  facts.unit = frame_metadata(*grid, kUnitMetadata, {"mm", "m", "um"});
  std::lock_guard<std::mutex> lock(mutex_);
  facts_[size_t(i)] = facts;
  read_index_ = i;
  read_grid_ = grid;
  return facts;
}

std::shared_ptr<const ScalarGrid> VdbFile::load(int i) const {
  openvdb::GridBase::Ptr stored;
  std::optional<GridFacts> scanned;  // facts() of this very grid object, when it is the one read for them
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (i == read_index_) {
      stored = std::move(read_grid_);
      scanned = facts_[size_t(i)];
    }
    read_index_ = -1;
    read_grid_.reset();
  }
  if (!stored) stored = read_grid(i);
  const std::string what = describe(i);
  if (!is_scalar_grid(*stored))
    throw Unsupported(what + " is a " + value_type_name(*stored) +
                      " grid; isoform contours scalar grids only");
  auto out = std::make_shared<ScalarGrid>();
  out->index_to_world = to_affine(stored->transform(), what);
  const openvdb::FloatGrid::Ptr grid = to_float_grid(stored);
  if (grid->tree().activeVoxelCount() == 0)
    throw FormatError(what + " is empty (no active voxels)");
  // After the conversion, so that doubles beyond float range are caught too.
  // A float grid that facts() scanned (and found finite) is not scanned again.
  ValueScan scan;
  if (scanned && grid == stored) {
    scan.min = scanned->value_min;
    scan.max = scanned->value_max;
  } else {
    scan = scan_values(grid->tree());
    require_finite(scan, grid->background(), grid == stored ? what : what + " (as float)");
  }
  out->name = grid->getName();
  out->grid_class = to_grid_class(grid->getGridClass());
  out->background = grid->background();
  out->value_min = scan.min;
  out->value_max = scan.max;
  out->bricks = std::make_shared<LeafBricks>(grid);
  out->active_bricks = std::make_shared<ActiveBricks>(grid);
  return out;
}

std::shared_ptr<VolumeFile> open_vdb(const std::string& path) {
  return std::make_shared<VdbFile>(path);
}

}  // namespace isoform::vdbio
