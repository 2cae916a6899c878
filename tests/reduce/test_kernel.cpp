// The kernel of the platelet polygon (kernel.h) on hand-checked polygons.
#include <gtest/gtest.h>

#include "libcore/reduce/kernel.h"

namespace isoform::reduce {
namespace {

using Ring = std::vector<Eigen::Vector2d>;

TEST(Kernel, ConvexSquareIsItsOwnKernel) {
  const Ring square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto c = kernel_centroid(square, 0.0);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR((*c)(0), 0.5, 1e-12);
  EXPECT_NEAR((*c)(1), 0.5, 1e-12);
}

// An L: star-shaped around the unit square at its corner only, whose
// centroid (0.5, 0.5) is not the L's own (7/12, 7/12).
TEST(Kernel, LShapeKernelIsTheCornerSquare) {
  const Ring l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  auto c = kernel_centroid(l, 0.0);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR((*c)(0), 0.5, 1e-12);
  EXPECT_NEAR((*c)(1), 0.5, 1e-12);
  // Pulled in by a hundredth of each edge: the sides of length 2 by 0.02,
  // the inner ones of length 1 by 0.01: [0.02, 0.99]^2.
  c = kernel_centroid(l, 0.01);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR((*c)(0), 0.505, 1e-12);
  EXPECT_NEAR((*c)(1), 0.505, 1e-12);
}

TEST(Kernel, NoKernelNoPoint) {
  // A U: the notch's two sides see each other's backs (x >= 2 and x <= 1).
  const Ring u{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  EXPECT_FALSE(kernel_centroid(u, 0.0).has_value());
  // Clockwise: every interior point is right of the edges.
  const Ring clockwise{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  EXPECT_FALSE(kernel_centroid(clockwise, 0.0).has_value());
  // A margin that closes a thin kernel: the strip 0.1 high loses 0.1 at
  // the bottom (an edge of length 10) alone.
  const Ring strip{{0, 0}, {10, 0}, {10, 0.1}, {0, 0.1}};
  EXPECT_TRUE(kernel_centroid(strip, 0.0).has_value());
  EXPECT_FALSE(kernel_centroid(strip, 0.01).has_value());
  // Too few corners, or a repeated one.
  EXPECT_FALSE(kernel_centroid(Ring{{0, 0}, {1, 0}}, 0.0).has_value());
  EXPECT_FALSE(kernel_centroid(Ring{{0, 0}, {1, 0}, {1, 0}, {0, 1}}, 0.0).has_value());
}

// The kernel's point for a fitted point: outside the kernel, its nearest
// point on the kernel's boundary moved a quarter of the way to the
// kernel's centroid; inside, the centroid.
TEST(Kernel, PointForTheFittedOneIsNearItInsideTheKernel) {
  const Ring l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};  // kernel [0, 1]^2, centroid (0.5, 0.5)
  auto x = kernel_point(l, 0.0, {1.5, 1.5});                    // nearest: the corner (1, 1)
  ASSERT_TRUE(x.has_value());
  EXPECT_NEAR((*x)(0), 0.875, 1e-12);
  EXPECT_NEAR((*x)(1), 0.875, 1e-12);
  x = kernel_point(l, 0.0, {1.8, 0.4});  // nearest: (1, 0.4) on the kernel's right side
  ASSERT_TRUE(x.has_value());
  EXPECT_NEAR((*x)(0), 0.875, 1e-12);
  EXPECT_NEAR((*x)(1), 0.425, 1e-12);
  x = kernel_point(l, 0.0, {0.3, 0.2});  // inside: the centroid
  ASSERT_TRUE(x.has_value());
  EXPECT_NEAR((*x)(0), 0.5, 1e-12);
  EXPECT_NEAR((*x)(1), 0.5, 1e-12);
  const Ring u{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  EXPECT_FALSE(kernel_point(u, 0.0, {1.5, 0.5}).has_value());
  // The kernel as a polygon: the L's is the unit square, counter-clockwise.
  const auto k = polygon_kernel(l, 0.0);
  ASSERT_GE(k.size(), 4u);
  double area = 0;
  for (size_t i = 0; i < k.size(); ++i) area += k[i](0) * k[(i + 1) % k.size()](1) - k[(i + 1) % k.size()](0) * k[i](1);
  EXPECT_NEAR(area / 2, 1.0, 1e-12);
}

}  // namespace
}  // namespace isoform::reduce
