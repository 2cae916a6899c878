// Section 2.2, transparency: the rectangle count, colours and alpha, and the
// back-to-front order for several views.
#include <gtest/gtest.h>

#include <cmath>

#include "libcore/errors.h"
#include "libcore/visualize/stack.h"
#include "visualize_support.h"

namespace isoform::visualize {
namespace {

using test::make_grid;

// The key the order must follow: the depth of the rectangle's corner nearest the eye.
double key(const Mesh& m, size_t r, const Vec3d& view) {
  double k = HUGE_VAL;
  for (size_t c = 0; c < 4; ++c) {
    const float* p = &m.points[3 * (4 * r + c)];
    k = std::min(k, depth({p[0], p[1], p[2]}, view));
  }
  return k;
}

TEST(Stack, CountsAlphaAndBackToFrontOrder) {
  const auto g = make_grid({9, 7, 5}, [](int i, int j, int k) { return double(i * j - k); }, {1, 1, 2});
  StackSettings s;
  s.n = {4, 3, 2};
  s.transparency = 0.25;
  for (const Vec3d view : {Vec3d{-1, -1, -1}, Vec3d{1, 0.5, 0.25}, Vec3d{0, 0, 1}, Vec3d{0.2, -1, 0}}) {
    s.view = view;
    const Mesh m = transparency_stack(*g.grid, g.domain, s, ColourSettings{});
    // 3 nx ny nz + nx ny + nx nz + ny nz = 72 + 12 + 8 + 6.
    const size_t rects = 98;
    ASSERT_EQ(m.vertex_count(), 4 * rects);
    ASSERT_EQ(m.triangle_count(), 2 * rects);
    for (size_t r = 1; r < rects; ++r) EXPECT_GE(key(m, r - 1, view), key(m, r, view)) << "rectangle " << r;
    for (size_t v = 0; v < m.vertex_count(); ++v) EXPECT_EQ(m.colors[4 * v + 3], 191);  // 255 (1 - 0.25)
    // Every rectangle faces the eye.
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      const float* a = &m.points[3 * m.triangles[3 * t]];
      const float* b = &m.points[3 * m.triangles[3 * t + 1]];
      const float* c = &m.points[3 * m.triangles[3 * t + 2]];
      const Vec3d e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      const Vec3d n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      EXPECT_LE(depth(n, view), 1e-9);
    }
  }
}

TEST(Stack, LookingAlongZTheFarthestXyRectangleComesFirst) {
  const auto g = make_grid({3, 3, 3}, [](int i, int, int) { return double(i); });
  StackSettings s;
  s.n = {2, 2, 2};
  s.view = {0, 0, 1};  // the eye below, looking up: z = 2 is farthest
  const Mesh m = transparency_stack(*g.grid, g.domain, s, ColourSettings{});
  for (size_t c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(m.points[3 * c + 2], 2.0f);
  // The last rectangles are those touching z = 0 (their nearest corner).
  EXPECT_EQ(key(m, m.vertex_count() / 4 - 1, s.view), 0.0);
  // Colours: f = x on [0, 2], viridis; the vertex at x = 0 is the first control.
  for (size_t v = 0; v < m.vertex_count(); ++v)
    if (m.points[3 * v] == 0.0f) {
      EXPECT_EQ(m.colors[4 * v], 68);
    }
}

TEST(Stack, BadSettingsAreRefused) {
  const auto g = make_grid({3, 3, 3}, [](int, int, int) { return 0.0; });
  StackSettings s;
  s.n = {0, 2, 2};
  EXPECT_THROW(transparency_stack(*g.grid, g.domain, s, ColourSettings{}), InvalidArgument);
  s.n = {2, 2, 2};
  s.transparency = 1.5;
  EXPECT_THROW(transparency_stack(*g.grid, g.domain, s, ColourSettings{}), InvalidArgument);
  s.transparency = 0.5;
  s.view = {0, 0, 0};
  EXPECT_THROW(transparency_stack(*g.grid, g.domain, s, ColourSettings{}), InvalidArgument);
}

}  // namespace
}  // namespace isoform::visualize
