// Four doubles side by side, one vertex per lane, and the few operations
// the four-lane curvature paths need beyond + - * /, each with the bits of
// its scalar counterpart in every lane: IEEE square roots, std::abs,
// std::max and std::min with their argument order (which decides what a
// NaN gives), and a lane-wise choice.
#pragma once

#include <cmath>
#include <cstdint>

namespace isoform {

typedef double Lanes4 __attribute__((vector_size(32)));
typedef int64_t Mask4 __attribute__((vector_size(32)));  // a comparison's result: all ones or zero per lane
// Eight doubles: two groups of four side by side (the AVX-512 fits).
typedef double Lanes8 __attribute__((vector_size(64)));
// The bits of four or eight doubles, for integer arithmetic on them.
typedef uint64_t Bits4 __attribute__((vector_size(32)));
typedef uint64_t Bits8 __attribute__((vector_size(64)));

#define ISOFORM_LANES_INLINE inline __attribute__((always_inline))

// Four 3-vectors, one per lane.
struct Vec3Lanes {
  Lanes4 x, y, z;
};

ISOFORM_LANES_INLINE Lanes4 splat4(double x) { return Lanes4{x, x, x, x}; }

// Lane-wise: c ? a : b.
ISOFORM_LANES_INLINE Lanes4 select4(Mask4 c, Lanes4 a, Lanes4 b) {
  return (Lanes4)((c & (Mask4)a) | (~c & (Mask4)b));
}

// NOTE: lane by lane, which the sources that use it (built with
// -fno-math-errno, libcore/CMakeLists.txt: no errno to set for a negative
// argument) turn into one 256-bit square root in their AVX and AVX-512
// clones and two 128-bit ones in the baseline; each is the IEEE square root.
ISOFORM_LANES_INLINE Lanes4 sqrt4(Lanes4 x) {
  return Lanes4{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
}

// std::abs: the sign bit cleared.
ISOFORM_LANES_INLINE Lanes4 abs4(Lanes4 x) {
  const Mask4 magnitude = {INT64_MAX, INT64_MAX, INT64_MAX, INT64_MAX};
  return (Lanes4)((Mask4)x & magnitude);
}

// std::max(a, b) = a < b ? b : a, and std::min(a, b) = b < a ? b : a.
ISOFORM_LANES_INLINE Lanes4 max4(Lanes4 a, Lanes4 b) { return select4(a < b, b, a); }
ISOFORM_LANES_INLINE Lanes4 min4(Lanes4 a, Lanes4 b) { return select4(b < a, b, a); }

// True in the lanes where x is finite.
ISOFORM_LANES_INLINE Mask4 finite4(Lanes4 x) { return abs4(x) <= splat4(1.79769313486231570815e+308); }

}  // namespace isoform
