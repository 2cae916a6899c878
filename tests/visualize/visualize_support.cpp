// Grids, PNG decoding and temporary folders for the visualisation tests.
#include "visualize_support.h"

#include <png.h>

#include <filesystem>
#include <random>
#include <stdexcept>

namespace isoform::test {

TestGrid make_grid(const Index3& dims, const std::function<double(int, int, int)>& f,
                   const Vec3d& spacing, const Vec3d& origin) {
  std::vector<float> values;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) values.push_back(float(f(i, j, k)));
  DenseVolume volume("f", GridClass::Other, std::move(values), dims,
                     Affine::scale_translate(spacing, origin), "test-grid");
  TestGrid out;
  out.grid = volume.load(0);
  out.domain.what = "test-grid";
  out.domain.lo = {0, 0, 0};
  out.domain.hi = {dims[0] - 1, dims[1] - 1, dims[2] - 1};
  out.domain.to_world = out.grid->index_to_world;
  return out;
}

double trilinear_field(double x, double y, double z) {
  return 1.0 + 2.0 * x - 3.0 * y + 0.5 * z + 0.25 * x * y - 0.125 * y * z + 0.0625 * x * y * z;
}

std::vector<unsigned char> read_png(const std::string& path, int& width, int& height) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) throw std::runtime_error("cannot read " + path);
  image.format = PNG_FORMAT_RGBA;
  std::vector<unsigned char> pixels(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr))
    throw std::runtime_error("cannot decode " + path);
  width = int(image.width);
  height = int(image.height);
  return pixels;
}

TempFolder::TempFolder() {
  std::random_device random;
  path_ = (std::filesystem::temp_directory_path() / ("isoform-vis-" + std::to_string(random()))).string();
  std::filesystem::create_directories(path_);
}

TempFolder::~TempFolder() {
  std::error_code error;
  std::filesystem::remove_all(path_, error);
}

size_t TempFolder::entries() const {
  size_t n = 0;
  for (auto it = std::filesystem::directory_iterator(path_); it != std::filesystem::directory_iterator(); ++it) ++n;
  return n;
}

}  // namespace isoform::test
