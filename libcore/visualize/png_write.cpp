// PNG files through libpng: the image is encoded into memory, then written
// atomically with meshio's AtomicFile (temporary file, fsync, rename).
#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <string>
#include <vector>

#include "../errors.h"
#include "../meshio/atomic_file.h"
#include "image.h"

namespace isoform::visualize {
namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + size);
}

void no_flush(png_structp) {}

// libpng reports errors by longjmp; nothing with a destructor lives in this
// frame between setjmp and the end of encoding, so the jump is safe.
bool encode(const Image& image, const char* range_text, std::vector<unsigned char>* out,
            std::vector<png_bytep>* rows) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, info ? &info : nullptr);
    return false;
  }
  png_set_write_fn(png, out, append_bytes, no_flush);
  png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, PNG_COLOR_TYPE_RGBA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_text text;
  text.compression = PNG_TEXT_COMPRESSION_NONE;
  text.key = const_cast<char*>("isoform range");
  text.text = const_cast<char*>(range_text);
  text.text_length = 0;
  png_set_text(png, info, &text, 1);
  png_set_rows(png, info, rows->data());
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void save_png(const Image& image, const std::string& path) {
  if (image.width < 1 || image.height < 1 ||
      image.rgba.size() != 4 * size_t(image.width) * size_t(image.height))
    throw InvalidArgument("cannot save " + path + ": the image is empty or its pixels do not match its size");
  std::vector<png_bytep> rows(size_t(image.height));
  for (int y = 0; y < image.height; ++y)
    rows[size_t(y)] = const_cast<png_bytep>(&image.rgba[4 * size_t(y) * size_t(image.width)]);
  char range[64];
  std::snprintf(range, sizeof range, "%.9g %.9g", image.f_min, image.f_max);
  std::vector<unsigned char> bytes;
  if (!encode(image, range, &bytes, &rows)) throw IoError("cannot save " + path + ": PNG encoding failed");
  meshio::AtomicFile file(path);
  file.write(bytes.data(), bytes.size());
  file.commit();
}

}  // namespace isoform::visualize
