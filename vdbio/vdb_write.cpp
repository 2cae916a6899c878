// Writes a VolumeFile as an OpenVDB file, atomically: a temporary file in
// the same directory, checked, then renamed over the target.
#include "vdb_write.h"

#include <openvdb/io/File.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>

#include "libcore/errors.h"
#include "vdb_convert.h"
#include "vdb_file.h"
#include "vdb_layout.h"

namespace isoform::vdbio {

namespace {

namespace fs = std::filesystem;

void refuse_own_source(const VolumeFile& volume, const std::string& path) {
  const std::string source = volume.path();
  if (source.empty()) return;
  // equivalent() sees hard links and symlinks; the canonical names still
  // compare when one side no longer exists.
  std::error_code ec, ec_path, ec_source;
  const fs::path canonical_path = fs::weakly_canonical(path, ec_path);
  const fs::path canonical_source = fs::weakly_canonical(source, ec_source);
  const bool same = fs::equivalent(path, source, ec) ||
                    (!ec_path && !ec_source && canonical_path == canonical_source);
  if (same) throw InvalidArgument(path + ": refusing to overwrite the volume's own source file");
}

// The grids of an OpenVDB file as stored, scalar ones as float.
openvdb::GridCPtrVec grids_of_vdb(const VdbFile& file) {
  openvdb::GridCPtrVec grids;
  for (int i = 0; i < file.grid_count(); ++i) {
    const openvdb::GridBase::Ptr grid = file.read_grid(i);
    grids.push_back(is_scalar_grid(*grid) ? to_float_grid(grid) : grid);
  }
  return grids;
}

// A scalar grid of any other source, from its bricks: each brick's own
// samples (its cells' lower corners) that differ from the background, or,
// for grids whose defined samples are their active set (curvature results,
// where 0 is a value), every defined own sample.
openvdb::FloatGrid::Ptr grid_from_bricks(const ScalarGrid& source) {
  const float background = float(source.background);
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(background);
  grid->setName(source.name);
  grid->setGridClass(to_vdb_class(source.grid_class));
  grid->setTransform(to_transform(source.index_to_world));
  openvdb::FloatGrid::Accessor access = grid->getAccessor();
  Brick brick;
  for (size_t b = 0; b < source.bricks->brick_count(); ++b) {
    source.bricks->fill(b, brick);
    for (int k = 0; k < brick.cells[2]; ++k)
      for (int j = 0; j < brick.cells[1]; ++j)
        for (int i = 0; i < brick.cells[0]; ++i) {
          const float v = brick.value(i, j, k);
          if (!brick.is_defined(i, j, k) || (v == background && !source.defined_is_active)) continue;
          access.setValueOn(
              openvdb::Coord(brick.origin[0] + i, brick.origin[1] + j, brick.origin[2] + k), v);
        }
  }
  return grid;
}

openvdb::GridCPtrVec grids_of(const VolumeFile& volume) {
  if (const auto* vdb = dynamic_cast<const VdbFile*>(&volume)) return grids_of_vdb(*vdb);
  openvdb::GridCPtrVec grids;
  for (int i = 0; i < volume.grid_count(); ++i) {
    const GridFacts facts = volume.facts(i);
    if (!facts.is_scalar) continue;
    openvdb::FloatGrid::Ptr grid = grid_from_bricks(*volume.load(i));
    // The scan's frame and unit travel with the grid (vdb_file.h reads them).
    if (!facts.space.empty()) grid->insertMeta(kSpaceMetadata, openvdb::StringMetadata(facts.space));
    if (!facts.unit.empty()) grid->insertMeta(kUnitMetadata, openvdb::StringMetadata(facts.unit));
    grids.push_back(grid);
  }
  return grids;
}

// A file beside the target, removed unless it was renamed onto it.
class TempFile {
 public:
  explicit TempFile(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    path_ = target.parent_path() / ("." + target.filename().string() + ".tmp-" +
                                    std::to_string(::getpid()) + "-" + std::to_string(counter++));
  }
  ~TempFile() {
    std::error_code ec;
    if (!renamed_) fs::remove(path_, ec);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const fs::path& path() const { return path_; }
  void rename_to(const fs::path& target) {
    std::error_code ec;
    fs::rename(path_, target, ec);
    if (ec) throw IoError(target.string() + ": cannot replace it (" + ec.message() + ")");
    renamed_ = true;
  }

 private:
  fs::path path_;
  bool renamed_ = false;
};

}  // namespace

void write_vdb(const VolumeFile& volume, const std::string& path) {
  initialize_openvdb();
  refuse_own_source(volume, path);
  const fs::path target(path);
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(dir)) throw IoError(path + ": no such directory " + dir.string());
  const openvdb::GridCPtrVec grids = grids_of(volume);
  TempFile temp(fs::absolute(target));
  try {
    openvdb::io::File(temp.path().string()).write(grids);
  } catch (const openvdb::Exception& e) {
    throw IoError(path + ": cannot be written (" + e.what() + ")");
  }
  // io::File does not check its stream after writing; a full disk shows as
  // grids that end past the end of the file.
  try {
    read_vdb_grid_table(temp.path().string());
  } catch (const FormatError&) {
    throw IoError(path + ": writing it failed (the file came out short; is the disk full?)");
  }
  temp.rename_to(target);
}

}  // namespace isoform::vdbio
