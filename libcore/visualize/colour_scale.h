// The linear colour-index map of Section 2.2:
//   c = ceil( (f_max - f) / (f_max - f_min) c_min + (f - f_min) / (f_max - f_min) c_max )
// with c_min = 0 and c_max = levels - 1, and the index c read from a colour
// map at s = c / c_max.
#pragma once

#include <cstdint>
#include <vector>

#include "colour_map.h"

namespace isoform::visualize {

struct ColourScale {
  double f_min = 0.0, f_max = 1.0;
  int levels = 256;  // c_min = 0, c_max = levels - 1
  MapId map = MapId::Viridis;

  // The seed's integer index, clamped to [0, c_max]. When f_max = f_min
  // every value gets c_min.
  int index(double f) const;
  Rgb colour(double f) const;
  // Appends red, green, blue, alpha of f to rgba.
  void append_rgba(double f, uint8_t alpha, std::vector<uint8_t>& rgba) const;
};

// How the range is chosen (the C API's isoform_colour_options).
struct ColourSettings {
  MapId map = MapId::Viridis;
  int levels = 256;
  bool fixed_range = false;
  double range_min = 0.0, range_max = 1.0;
};

// The scale for values: the fixed range, or the least and greatest finite
// value (for the diverging map -m..m with m the greatest |f|, so that zero is
// the white middle). Throws InvalidArgument for levels outside 2..65536 or a
// fixed range that is empty or not finite.
ColourScale make_scale(const ColourSettings& settings, const std::vector<double>& values);

}  // namespace isoform::visualize
