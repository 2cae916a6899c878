// A dense block of samples in double precision with defined flags, covering
// a region of index space plus a margin of kGraphReach, from which the
// curvature of any point of the region can read its GraphSamples.
#pragma once

#include <cstdint>
#include <vector>

#include "graph_samples.h"

namespace isoform {

class GraphBlock {
 public:
  // The block for points [first, first + count) per axis; every sample
  // starts undefined.
  void reset(const Index3& first, const Index3& count);

  const Index3& first() const { return first_; }
  const Index3& count() const { return count_; }
  // Sample at global index p, which must lie within kGraphReach of the region.
  void set(const Index3& p, double value) {
    const size_t at = index(p);
    values_[at] = value;
    defined_[at] = 1;
  }
  bool is_defined(const Index3& p) const { return defined_[index(p)] != 0; }
  GraphSamples samples(const Index3& p) const;

  // Copies the defined samples of a brick (its own samples and its halo)
  // that fall inside the block.
  void add_brick(const Brick& brick);
  // Copies only a brick's own samples [origin, origin + cells) that are
  // defined and inside the block (neighbouring bricks).
  void add_brick_own(const Brick& brick);

 private:
  size_t index(const Index3& p) const {
    return (size_t(p[2] - lo_[2]) * size_t(dims_[1]) + size_t(p[1] - lo_[1])) * size_t(dims_[0]) +
           size_t(p[0] - lo_[0]);
  }
  void add_range(const Brick& brick, int from, int to_extra);

  Index3 first_{0, 0, 0}, count_{0, 0, 0}, lo_{0, 0, 0}, dims_{0, 0, 0};
  std::vector<double> values_;
  std::vector<uint8_t> defined_;
};

}  // namespace isoform
