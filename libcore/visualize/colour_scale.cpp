// The colour-index map of Section 2.2 and the choice of its range.
#include "colour_scale.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "../errors.h"

namespace isoform::visualize {

int ColourScale::index(double f) const {
  const double c_min = 0.0;
  const int c_max = levels - 1;
  if (!(f_max > f_min)) return 0;
  const double span = f_max - f_min;
  const double c = (f_max - f) / span * c_min + (f - f_min) / span * double(c_max);
  // NOTE: the seed's ceiling, less a relative 1e-9 so that a value that lands
  // on an integer index up to rounding (f = f_min + i span / c_max) keeps it.
  const double up = std::ceil(c - 1e-9 * double(c_max));
  return int(std::clamp(up, 0.0, double(c_max)));
}

Rgb ColourScale::colour(double f) const {
  return colour_map(map).at(double(index(f)) / double(levels - 1));
}

void ColourScale::append_rgba(double f, uint8_t alpha, std::vector<uint8_t>& rgba) const {
  const Rgb c = colour(f);
  rgba.insert(rgba.end(), {c[0], c[1], c[2], alpha});
}

ColourScale make_scale(const ColourSettings& settings, const std::vector<double>& values) {
  if (settings.levels < 2 || settings.levels > 65536)
    throw InvalidArgument("colour levels " + std::to_string(settings.levels) +
                          " outside 2..65536");
  ColourScale scale;
  scale.levels = settings.levels;
  scale.map = settings.map;
  if (settings.fixed_range) {
    if (!std::isfinite(settings.range_min) || !std::isfinite(settings.range_max) ||
        !(settings.range_max > settings.range_min))
      throw InvalidArgument("colour range " + std::to_string(settings.range_min) + ".." +
                            std::to_string(settings.range_max) + " is empty or not finite");
    scale.f_min = settings.range_min;
    scale.f_max = settings.range_max;
    return scale;
  }
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (double f : values) {
    if (!std::isfinite(f)) continue;
    lo = std::min(lo, f);
    hi = std::max(hi, f);
  }
  if (lo > hi) lo = hi = 0.0;
  if (settings.map == MapId::Diverging) {
    const double m = std::max(std::fabs(lo), std::fabs(hi));
    lo = -m;
    hi = m;
  }
  scale.f_min = lo;
  scale.f_max = hi;
  return scale;
}

}  // namespace isoform::visualize
