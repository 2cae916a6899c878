// A smooth surface defined piecewise over the triangles of a base mesh:
// the side-vertex surface of Chapter 6 (patch/) and the Loop limit surface
// it is compared with (compare/) both answer the same question, "where is the
// surface over base triangle t at barycentric (1-u-v, u, v)?", so the
// comparison study samples both at identical parameters.
#pragma once

#include <array>
#include <cstddef>

namespace isoform {

// One evaluated point. The parameter (u, v) is barycentric with respect to
// the base triangle's vertices (t0, t1, t2) in the order of the triangle
// table: weight 1-u-v on t0, u on t1, v on t2. Derivatives are with respect
// to u and v.
struct SurfaceSample {
  std::array<double, 3> point{};
  std::array<double, 3> normal{};  // unit; oriented like the base triangle
  std::array<double, 3> du{}, dv{};
  std::array<double, 3> duu{}, duv{}, dvv{};
  bool has_second = false;  // duu, duv, dvv are valid
};

class TriangleSurface {
 public:
  virtual ~TriangleSurface() = default;
  virtual size_t triangle_count() const = 0;
  // Evaluates the surface over base triangle `triangle` at (u, v), u, v >= 0,
  // u + v <= 1. Returns false when the surface is undefined there (the
  // sample is then left unspecified); never throws.
  virtual bool evaluate(size_t triangle, double u, double v, SurfaceSample& out) const = 0;
};

}  // namespace isoform
