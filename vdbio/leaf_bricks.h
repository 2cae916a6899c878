// Bricks over an OpenVDB float tree, one per 16^3 block of cells (2^3 leaf
// blocks) that holds an 8^3 block of cells that can hold a crossing. Every
// brick is aligned (origin a multiple of 16, cells {16, 16, 16}) and every
// sample is defined: values off the leaves come from tiles and the
// background, so a sparse grid's contour closes wherever it leaves the
// active region. The other blocks of a brick lie, with their cells'
// corners, in tiles and the background, which in a valid grid leaves
// separate from values on the other side of the isovalue: their cells add
// nothing.
#pragma once

#include <openvdb/openvdb.h>

#include <vector>

#include "libcore/volume.h"

namespace isoform::vdbio {

class LeafBricks : public BrickSource {
 public:
  // Keeps the grid alive and finds the candidate 8^3 blocks once:
  // - every leaf node, and the 7 blocks at offsets {0,-8}^3 below it, whose
  //   cells reach into the leaf with their upper corners;
  // - for every active tile (any level), the blocks holding cells that have
  //   corners both inside and outside it: a fog volume's constant interior
  //   is an active tile whose boundary must still be contoured. Inactive
  //   tiles add nothing; in a valid grid leaves separate them from values
  //   on the other side of the isovalue.
  explicit LeafBricks(openvdb::FloatGrid::ConstPtr grid);

  size_t brick_count() const override { return origins_.size(); }
  // Thread-safe: each call reads the tree through its own accessor. It
  // probes the 64 blocks around the brick once and copies from leaf buffers;
  // a block without a leaf lies in one tile or the background, so one value
  // stands for all of it.
  void fill(size_t index, Brick& out) const override;
  // Reads the tree directly: every sample of the box, active or not, from
  // leaves, tiles or the background (`outside` is not needed). Thread-safe.
  void fill_region(const Index3& lo, const Index3& dims, float outside,
                   std::vector<float>& out) const override;

  // From the value ranges of the 27 blocks that hold the brick's corner
  // samples (its own 8 and the 19 above them), found once by the
  // constructor: false when all of them lie on one side of the isovalue.
  bool may_cross(size_t index, double isovalue) const override {
    return double(corner_min_[index]) < isovalue && double(corner_max_[index]) >= isovalue;
  }

  const openvdb::FloatGrid::ConstPtr& grid() const { return grid_; }
  // Brick origins (the first cell of each), sorted and unique.
  const std::vector<openvdb::Coord>& origins() const { return origins_; }

 private:
  openvdb::FloatGrid::ConstPtr grid_;
  std::vector<openvdb::Coord> origins_;
  // Per brick: the smallest and largest value its corner samples can take.
  std::vector<float> corner_min_, corner_max_;
};

}  // namespace isoform::vdbio
