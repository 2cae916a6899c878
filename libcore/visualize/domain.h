// The domain D of a grid for Chapter 2: the box of index positions
// [lo, hi] (the grid's active bounding box, inclusive), its transform to
// world space, and the dense samples over a part of it with trilinear
// interpolation between them (Section 2.2: "trilinear interpolation of those
// eight given function values").
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "../volume.h"

namespace isoform::visualize {

struct Domain {
  std::string what;  // names the grid in messages ("smoke.vdb, grid 'density'")
  Index3 lo{0, 0, 0}, hi{0, 0, 0};
  Affine to_world;

  Vec3d world(const Vec3d& index) const { return to_world.apply(index); }
  // The index position of a world point (the transform inverted).
  Vec3d index(const Vec3d& world) const;
  // World bounding box of the domain's eight corners.
  Vec3d world_min() const;
  Vec3d world_max() const;
  // Throws InvalidArgument naming `what` when p lies outside [lo, hi] by
  // more than a relative 1e-9 of the domain's size.
  void require_inside(const Vec3d& p, const std::string& label) const;
};

// Dense samples of one grid over the index box [lo, lo + dims).
class SampleRegion {
 public:
  // Reads the box from the grid's bricks (BrickSource::fill_region).
  SampleRegion(const ScalarGrid& grid, const Index3& lo, const Index3& hi);

  float at(int i, int j, int k) const {
    return values_[(size_t(k - lo_[2]) * size_t(dims_[1]) + size_t(j - lo_[1])) * size_t(dims_[0]) +
                   size_t(i - lo_[0])];
  }
  // The trilinear interpolant of the eight samples of the cell holding p
  // (index space; p is clamped into the region, whose upper face belongs
  // to the last cell).
  double trilinear(const Vec3d& p) const;

 private:
  Index3 lo_, dims_;
  std::vector<float> values_;
};

}  // namespace isoform::visualize
