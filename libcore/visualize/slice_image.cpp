// A slice as an image, and the colour bar beside it.
#include <cmath>
#include <limits>

#include "slices.h"

namespace isoform::visualize {
namespace {

void put(Image& image, int x, int y, const Rgb& c) {
  uint8_t* p = &image.rgba[4 * (size_t(y) * size_t(image.width) + size_t(x))];
  p[0] = c[0];
  p[1] = c[1];
  p[2] = c[2];
  p[3] = 255;
}

// The bar spans the image's height: its top row is f_max, its bottom row
// f_min, each row coloured through the same index map as the slice, inside
// a one-pixel black frame.
void draw_colour_bar(Image& image, int x0, int width, const ColourScale& scale) {
  const int h = image.height;
  for (int y = 0; y < h; ++y) {
    const double s = h > 1 ? double(h - 1 - y) / double(h - 1) : 0.0;
    const Rgb c = scale.colour(scale.f_min + s * (scale.f_max - scale.f_min));
    for (int x = x0; x < x0 + width; ++x) {
      const bool frame = x == x0 || x == x0 + width - 1 || y == 0 || y == h - 1;
      put(image, x, y, frame ? Rgb{0, 0, 0} : c);
    }
  }
}

}  // namespace

Image slice_image(const Slice& slice, const ColourScale& scale, bool colour_bar) {
  Image image;
  const int gap = colour_bar ? std::max(4, slice.nu / 32) : 0;
  const int bar = colour_bar ? std::max(8, slice.nu / 12) : 0;
  image.width = slice.nu + gap + bar;
  image.height = slice.nv;
  image.f_min = scale.f_min;
  image.f_max = scale.f_max;
  image.rgba.assign(4 * size_t(image.width) * size_t(image.height), 255);
  image.values.assign(size_t(image.width) * size_t(image.height),
                      std::numeric_limits<float>::quiet_NaN());
  for (int row = 0; row < slice.nv; ++row) {
    const int iv = slice.nv - 1 - row;
    for (int iu = 0; iu < slice.nu; ++iu) {
      const double f = slice.value(iu, iv);
      put(image, iu, row, scale.colour(f));
      image.values[size_t(row) * size_t(image.width) + size_t(iu)] = float(f);
    }
  }
  if (colour_bar) draw_colour_bar(image, slice.nu + gap, bar, scale);
  return image;
}

}  // namespace isoform::visualize
