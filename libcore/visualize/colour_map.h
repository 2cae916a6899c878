// Colour maps as data: a table of control colours at equal steps over [0, 1],
// read by linear interpolation between neighbouring controls. Section 2.2
// refers to "a predefined color map" indexed by integers; colour_scale.h
// turns a value into such an index, and the index into a position here.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace isoform::visualize {

using Rgb = std::array<uint8_t, 3>;

enum class MapId { Viridis = 0, Diverging = 1, GreenWhite = 2 };

struct ColourMap {
  std::string name;
  std::vector<Rgb> controls;  // two or more, at s = 0, 1/(n-1), ..., 1
  // The colour at s in [0, 1] (clamped), interpolated linearly per channel
  // between the two controls around s, rounded to the nearest integer.
  Rgb at(double s) const;
};

// The built-in maps: viridis (9 controls), a diverging blue-white-red map
// whose middle control (s = 0.5) is white, and green to white (Figures
// 2.2 to 2.4: "Low values are mapped to green, high ones to white").
const ColourMap& colour_map(MapId id);

}  // namespace isoform::visualize
