// An OpenVDB file as a VolumeFile.
#pragma once

#include <openvdb/version.h>

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "libcore/volume.h"
#include "vdb_check.h"

// Declared rather than included: the C API sources include this header,
// and OpenVDB's headers would put default-visibility symbols into them.
namespace openvdb {
OPENVDB_USE_VERSION_NAMESPACE
namespace OPENVDB_VERSION_NAME {
class GridBase;
}
}  // namespace openvdb

namespace isoform::vdbio {

// Grid metadata naming the patient frame and unit of a scan's world
// coordinates (GridFacts::space, ::unit), written when a NIfTI or NRRD scan
// is converted and read back, so that the .vdb says what the scan said.
inline constexpr const char* kSpaceMetadata = "isoform_space";
inline constexpr const char* kUnitMetadata = "isoform_unit";

// Opening walks the file's header, grid table, metadata and transforms
// (vdb_check.h) before OpenVDB reads every grid's metadata; each grid's tree
// is walked before OpenVDB reads it; voxel data are read when a grid is described or loaded, each
// time through a fresh io::File, so calls may run on several threads at
// once. The (small) facts are kept, and the grid last read for its facts
// until it is loaded (so that describing a grid, then loading it, reads it
// once); loaded grids are the caller's to keep (the C API handle does).
class VdbFile : public VolumeFile {
 public:
  explicit VdbFile(std::string path);

  std::string path() const override { return path_; }
  int grid_count() const override { return int(grids_.size()); }
  // Value range and background are given for scalar grids only (0 for
  // vector, bool and mask grids); active count and bounding box for all.
  GridFacts facts(int i) const override;
  // Float, double, int32 and int64 grids, converted to float. Throws
  // Unsupported for other value types, FormatError for a grid without active
  // voxels or with a NaN or infinite value (active or not: the bricks see
  // every stored value).
  std::shared_ptr<const ScalarGrid> load(int i) const override;

  // Grid i as stored (any value type), its tree read in full; for writers
  // that copy grids as they are.
  std::shared_ptr<openvdb::GridBase> read_grid(int i) const;

 private:
  std::string describe(int i) const;  // "PATH: grid 'NAME'" for messages

  std::string path_;
  VdbLayout layout_;                                             // as checked at open
  std::vector<std::string> names_;                               // as io::File::readGrid takes them
  std::vector<std::shared_ptr<const openvdb::GridBase>> grids_;  // metadata and transform only
  mutable std::mutex mutex_;
  mutable std::vector<std::optional<GridFacts>> facts_;
  mutable int read_index_ = -1;                            // the grid facts() read last
  mutable std::shared_ptr<openvdb::GridBase> read_grid_;  // until load() takes it
};

// Throws IoError (missing, unreadable), FormatError (not a VDB, truncated or
// damaged) or Unsupported (a grid type or file version OpenVDB cannot read),
// each naming the file.
std::shared_ptr<VolumeFile> open_vdb(const std::string& path);

}  // namespace isoform::vdbio
