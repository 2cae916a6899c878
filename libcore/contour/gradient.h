// Section 3.4 of Hamann (1991): the Zucker-Hummel 3x3x3 gradient operator
// (Theorem 3.8, (3.17)) at the samples of a brick.
#pragma once

#include "../volume.h"

namespace isoform {

// The gradient estimate at sample (i, j, k) of the brick (each in
// [0, cells]), in index space (per voxel), pointing toward increasing f:
// component x is the sum over r = +-1 and s, t in {-1, 0, 1} of
// r c f(i+r, j+s, k+t) with c = 1 / sqrt(|r| + |s| + |t|), and likewise for
// y and z, divided by the operator's response to f = x so that a linear f
// gives its exact gradient. An undefined neighbour (outside a dense array) is
// extrapolated linearly from the sample and its opposite neighbour.
Vec3d zucker_hummel(const Brick& brick, int i, int j, int k);

// The same where all 26 neighbours are defined: `at` points at the sample,
// rows are `row` samples apart and slices `slice` apart. The same sums,
// grouped by axis (equal to zucker_hummel() up to rounding).
Vec3d zucker_hummel_inside(const float* at, size_t row, size_t slice);

// zucker_hummel_inside() at the four samples at, at + 1, at + 2, at + 3 of
// one row, into out[0..3], the same bits, four at a time in vector lanes.
// Only where has_zucker_hummel_four() (AVX).
bool has_zucker_hummel_four();
void zucker_hummel_four(const float* at, size_t row, size_t slice, Vec3d out[4]);

}  // namespace isoform
