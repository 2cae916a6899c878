// Section 2.3: slice values at grid points and between them, positions
// outside the domain, the image's pixels (decoded from the PNG), the meshes.
#include <gtest/gtest.h>

#include <cmath>

#include "libcore/errors.h"
#include "libcore/meshio/meshio.h"
#include "libcore/visualize/slices.h"
#include "visualize_support.h"

namespace isoform::visualize {
namespace {

using test::make_grid;

double bumpy(int i, int j, int k) { return std::sin(0.9 * i + 0.4 * j) * std::cos(0.3 * k) + 0.1 * k; }

TEST(Slices, AtGridPointsTheSlicesAreTheGridValues) {
  const auto g = make_grid({5, 5, 5}, bumpy);
  SliceSettings s;
  s.position = {0.5, 0.25, 1.0};  // index planes x = 2, y = 1, z = 4
  s.resolution = 5;               // one sample per grid point
  const auto slices = sample_slices(*g.grid, g.domain, s);
  for (int axis = 0; axis < 3; ++axis) {
    const Slice& sl = slices[axis];
    ASSERT_EQ(sl.nu, 5);
    ASSERT_EQ(sl.nv, 5);
    for (int iv = 0; iv < 5; ++iv)
      for (int iu = 0; iu < 5; ++iu) {
        int ijk[3];
        ijk[axis] = axis == 0 ? 2 : axis == 1 ? 1 : 4;
        ijk[sl.u_axis] = iu;
        ijk[sl.v_axis] = iv;
        EXPECT_EQ(sl.value(iu, iv), double(float(bumpy(ijk[0], ijk[1], ijk[2])))) << axis;
      }
  }
}

TEST(Slices, BetweenGridPointsTheSlicesAreTrilinear) {
  const auto g = make_grid({5, 5, 5}, [](int i, int j, int k) { return test::trilinear_field(i, j, k); },
                           {0.5, 0.5, 0.5}, {1, 2, 3});
  SliceSettings s;
  s.position = {0.3, 0.55, 0.9};  // index 1.2, 2.2, 3.6
  s.resolution = 9;               // half-voxel steps
  const auto slices = sample_slices(*g.grid, g.domain, s);
  for (const Slice& sl : slices)
    for (int iv = 0; iv < sl.nv; ++iv)
      for (int iu = 0; iu < sl.nu; ++iu) {
        const Vec3d p = sl.point(iu, iv);
        EXPECT_NEAR(sl.value(iu, iv), test::trilinear_field(p[0], p[1], p[2]), 1e-5);
      }
  EXPECT_DOUBLE_EQ(slices[0].point(0, 0)[0], 1.2);
  EXPECT_DOUBLE_EQ(slices[2].point(3, 5)[1], 2.5);
}

TEST(Slices, WorldPositionsAndPositionsOutsideTheDomain) {
  const auto g = make_grid({5, 5, 5}, bumpy, {0.5, 0.5, 0.5}, {1, 2, 3});
  SliceSettings s;
  s.world = true;
  s.position = {2.0, 2.5, 5.0};  // index 2, 1, 4
  const auto slices = sample_slices(*g.grid, g.domain, s);
  EXPECT_NEAR(slices[0].c, 2.0, 1e-12);
  EXPECT_NEAR(slices[1].c, 1.0, 1e-12);
  EXPECT_NEAR(slices[2].c, 4.0, 1e-12);
  s.position = {2.0, 2.5, 5.1};
  EXPECT_THROW(sample_slices(*g.grid, g.domain, s), InvalidArgument);
  s.world = false;
  s.position = {0.5, 1.5, 0.5};
  try {
    sample_slices(*g.grid, g.domain, s);
    FAIL() << "no error for a position outside the domain";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("outside the domain"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("test-grid"), std::string::npos) << e.what();
  }
  s.position = {0.5, 0.5, 0.5};
  s.resolution = 1;
  EXPECT_THROW(sample_slices(*g.grid, g.domain, s), InvalidArgument);
}

// f = x on [0, 4]^3 with 5 levels of viridis: column iu has index iu, the
// colour of control 2 iu.
TEST(SliceImage, KnownFieldGivesKnownPixelsInThePng) {
  const auto g = make_grid({5, 5, 5}, [](int i, int, int) { return double(i); });
  SliceSettings s;
  s.resolution = 5;
  const auto slices = sample_slices(*g.grid, g.domain, s);
  ColourSettings c;
  c.levels = 5;
  const ColourScale scale = slices_scale(slices, c);
  EXPECT_EQ(scale.f_min, 0.0);
  EXPECT_EQ(scale.f_max, 4.0);
  const Image image = slice_image(slices[2], scale, true);  // z slice: u = x, v = y
  test::TempFolder dir;
  save_png(image, dir.file("z.png"));
  int w = 0, h = 0;
  const auto pixels = test::read_png(dir.file("z.png"), w, h);
  ASSERT_EQ(w, image.width);
  ASSERT_EQ(h, 5);
  ASSERT_GT(w, 5 + 8);  // the slice, a gap and the bar
  const Rgb expected[5] = {{68, 1, 84}, {62, 73, 137}, {38, 130, 142}, {53, 183, 121}, {253, 231, 37}};
  for (int row = 0; row < 5; ++row)
    for (int col = 0; col < 5; ++col) {
      const unsigned char* p = &pixels[4 * (size_t(row) * w + col)];
      EXPECT_EQ(p[0], expected[col][0]);
      EXPECT_EQ(p[1], expected[col][1]);
      EXPECT_EQ(p[2], expected[col][2]);
      EXPECT_EQ(p[3], 255);
    }
  // The bar runs from f_max (row 0) to f_min (row 4) inside a black frame:
  // row 1 is f = 3 (index 3), row 3 is f = 1 (index 1).
  const int bar_middle = w - 3;
  const unsigned char* upper = &pixels[4 * (size_t(1) * w + bar_middle)];
  const unsigned char* lower = &pixels[4 * (size_t(3) * w + bar_middle)];
  EXPECT_EQ(upper[0], 53);
  EXPECT_EQ(upper[1], 183);
  EXPECT_EQ(lower[0], 62);
  EXPECT_EQ(lower[1], 73);
  EXPECT_EQ(pixels[4 * (size_t(2) * w + w - 1)], 0);
}

TEST(SliceImage, ImageRowsRunDownwardInV) {
  const auto g = make_grid({5, 5, 5}, [](int, int j, int) { return double(j); });
  SliceSettings s;
  s.resolution = 5;
  const auto slices = sample_slices(*g.grid, g.domain, s);
  const ColourScale scale = slices_scale(slices, ColourSettings{});
  const Image image = slice_image(slices[2], scale, false);  // v = y
  ASSERT_EQ(image.width, 5);
  EXPECT_EQ(image.values[0], 4.0f);                 // top row: y = 4
  EXPECT_EQ(image.values[4 * 5 + 3], 0.0f);         // bottom row: y = 0
}

TEST(SliceMesh, PlaneSurfaceAndCurveCounts) {
  const auto g = make_grid({5, 4, 3}, bumpy, {1, 1, 1}, {0, 0, 0});
  SliceSettings s;
  s.resolution = 9;
  const auto slices = sample_slices(*g.grid, g.domain, s);
  const ColourScale scale = slices_scale(slices, ColourSettings{});
  const Slice& z = slices[2];  // u = x (extent 4): 9, v = y (extent 3): 7
  ASSERT_EQ(z.nu, 9);
  ASSERT_EQ(z.nv, 7);
  const Mesh plane = slice_mesh(z, g.domain, scale, SliceKind::Plane, 0.25);
  EXPECT_EQ(plane.vertex_count(), 63u);
  EXPECT_EQ(plane.triangle_count(), 2u * 8 * 6);
  EXPECT_EQ(plane.colors.size(), 4u * 63);
  for (size_t v = 0; v < plane.vertex_count(); ++v) {
    EXPECT_FLOAT_EQ(plane.points[3 * v + 2], 1.0f);  // the plane z = 1
    EXPECT_FLOAT_EQ(plane.normals[3 * v + 2], 1.0f);
  }
  const Mesh surface = slice_mesh(z, g.domain, scale, SliceKind::Surface, 0.25);
  float top = -1e9f, bottom = 1e9f;
  for (size_t v = 0; v < surface.vertex_count(); ++v) {
    top = std::max(top, surface.points[3 * v + 2]);
    bottom = std::min(bottom, surface.points[3 * v + 2]);
  }
  EXPECT_GE(bottom, 1.0f - 1e-6f);
  EXPECT_LE(top, 1.0f + 0.25f * 4.0f + 1e-5f);
  const Mesh curves = slice_mesh(z, g.domain, scale, SliceKind::Curves, 0.25);
  EXPECT_EQ(curves.triangle_count(), 0u);
  EXPECT_EQ(curves.edge_count(), size_t(7 * 8 + 9 * 6));
  EXPECT_EQ(curves.points, surface.points);
  test::TempFolder dir;
  EXPECT_NO_THROW(save_mesh(curves, dir.file("c.ply")));
  const Mesh outline = domain_outline(g.domain);
  EXPECT_EQ(outline.edge_count(), 12u);
}

}  // namespace
}  // namespace isoform::visualize
