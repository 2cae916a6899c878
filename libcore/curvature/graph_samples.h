// What the curvature of one grid point reads: the samples around it and the
// grid's index-to-world map.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "../volume.h"

namespace isoform {

// How far from the point a fit may read, in samples per axis. The default
// fit's box of 7 samples per axis can shift by 3 at the data's edge, so it
// reaches 6; every caller must make offsets in [-6, 6]^3 readable (marked
// undefined where there is no data). At most the lattice pitch of bricks
// (8 for vdbio's leaves), so a brick's neighbours cover it.
constexpr int kGraphReach = 6;

// Samples around one grid point, in double precision: value and defined
// flag at index offset (i, j, k), each in [-kGraphReach, kGraphReach].
struct GraphSamples {
  const double* values = nullptr;    // at the point itself
  const uint8_t* defined = nullptr;  // at the point itself; 1 = defined
  std::ptrdiff_t stride[3] = {1, 0, 0};

  std::ptrdiff_t at(int i, int j, int k) const { return i * stride[0] + j * stride[1] + k * stride[2]; }
  bool is_defined(int i, int j, int k) const { return defined[at(i, j, k)] != 0; }
  double value(int i, int j, int k) const { return values[at(i, j, k)]; }
};

// The linear part of a grid's index-to-world map and its inverse
// transpose: world offsets of index offsets, and world gradients of index
// gradients.
struct GraphAxes {
  double linear[3][3];
  double inverse_transpose[3][3];

  // Throws InvalidArgument when the map is singular.
  static GraphAxes of(const Affine& index_to_world);
  std::array<double, 3> world_offset(int i, int j, int k) const;
  std::array<double, 3> world_gradient(const std::array<double, 3>& index_gradient) const;
};

}  // namespace isoform
