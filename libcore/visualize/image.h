// An RGBA image with the values behind its pixels, and its PNG file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace isoform::visualize {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;   // 4 per pixel, rows top to bottom
  std::vector<float> values;   // 1 per pixel, NaN where no value was sampled
  double f_min = 0.0, f_max = 0.0;  // the colour scale's range
};

// Writes an 8-bit RGBA PNG through libpng, with a tEXt chunk "isoform range"
// holding "f_min f_max". Atomic (meshio's AtomicFile). Throws IoError.
void save_png(const Image& image, const std::string& path);

}  // namespace isoform::visualize
