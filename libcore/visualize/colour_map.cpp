// The built-in colour maps and their interpolation.
#include "colour_map.h"

#include <algorithm>
#include <cmath>

namespace isoform::visualize {

Rgb ColourMap::at(double s) const {
  const double clamped = std::isfinite(s) ? std::clamp(s, 0.0, 1.0) : 0.0;
  const double x = clamped * double(controls.size() - 1);
  const size_t i = std::min(size_t(x), controls.size() - 2);
  const double t = x - double(i);
  Rgb out;
  for (int c = 0; c < 3; ++c)
    out[c] = uint8_t(std::lround((1.0 - t) * controls[i][c] + t * controls[i + 1][c]));
  return out;
}

const ColourMap& colour_map(MapId id) {
  // viridis at s = 0, 1/8, ..., 1 (the published 9-step table).
  static const ColourMap viridis{"viridis",
                                 {{68, 1, 84}, {72, 40, 120}, {62, 73, 137}, {49, 104, 142},
                                  {38, 130, 142}, {31, 158, 137}, {53, 183, 121}, {110, 206, 88},
                                  {253, 231, 37}}};
  // Blue below zero, white at zero (the middle control), red above.
  static const ColourMap diverging{"diverging",
                                   {{33, 102, 172}, {103, 169, 207}, {209, 229, 240},
                                    {255, 255, 255}, {253, 219, 199}, {239, 138, 98},
                                    {178, 24, 43}}};
  static const ColourMap green_white{"green-white", {{0, 128, 0}, {255, 255, 255}}};
  switch (id) {
    case MapId::Diverging: return diverging;
    case MapId::GreenWhite: return green_white;
    case MapId::Viridis: break;
  }
  return viridis;
}

}  // namespace isoform::visualize
