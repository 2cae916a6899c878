// Bricks over an OpenVDB float tree whose `defined` flags are its active
// voxels: what the curvature of graphs reads (ScalarGrid::active_bricks),
// so that results exist at the active voxels and nowhere else, and fits use
// active neighbours only.
#pragma once

#include <openvdb/openvdb.h>

#include <vector>

#include "libcore/volume.h"

namespace isoform::vdbio {

class ActiveBricks : public BrickSource {
 public:
  // One brick per 8^3 block that holds an active voxel: every leaf with an
  // active voxel, and every 8^3 block of each active tile. Origins sorted.
  explicit ActiveBricks(openvdb::FloatGrid::ConstPtr grid);

  size_t brick_count() const override { return origins_.size(); }
  // Thread-safe: each call reads the tree through its own accessor. Every
  // sample (halo included) holds the tree's value; defined = active.
  void fill(size_t index, Brick& out) const override;

 private:
  openvdb::FloatGrid::ConstPtr grid_;
  std::vector<openvdb::Coord> origins_;
};

}  // namespace isoform::vdbio
