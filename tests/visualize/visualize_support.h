// Grids made in code for the visualisation tests, and a PNG decoder.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "libcore/visualize/domain.h"

namespace isoform::test {

// An n0 x n1 x n2 dense grid of f(i, j, k) at index (i, j, k), with the
// given spacing and origin, and its domain (the whole array).
struct TestGrid {
  std::shared_ptr<const ScalarGrid> grid;
  visualize::Domain domain;
};
TestGrid make_grid(const Index3& dims, const std::function<double(int, int, int)>& f,
                   const Vec3d& spacing = {1, 1, 1}, const Vec3d& origin = {0, 0, 0});

// A trilinear polynomial: interpolation reproduces it exactly.
double trilinear_field(double x, double y, double z);

// Decodes an 8-bit RGBA PNG with libpng; width and height out.
std::vector<unsigned char> read_png(const std::string& path, int& width, int& height);

// A fresh temporary directory, removed with its contents.
class TempFolder {
 public:
  TempFolder();
  ~TempFolder();
  std::string file(const std::string& name) const { return path_ + "/" + name; }
  size_t entries() const;

 private:
  std::string path_;
};

}  // namespace isoform::test
