// The slicing method of Section 2.3: the planes P1: x = c1, P2: y = c2,
// P3: z = c3 (index axes, mapped to world by the grid's transform) cut the
// domain D in areas A_i, and the function is evaluated on a (k_i + 1)(l_i + 1)
// rectilinear grid over each. From those samples come images (slice_image.h)
// and meshes: Gouraud-coloured planes, and the graphs of the slice functions
// as shaded surfaces (index triples I1, I2) or curve networks (Figure 2.9).
#pragma once

#include <array>
#include <vector>

#include "../mesh.h"
#include "colour_scale.h"
#include "domain.h"
#include "image.h"

namespace isoform::visualize {

struct SliceSettings {
  Vec3d position{0.5, 0.5, 0.5};  // c1, c2, c3
  bool world = false;             // false: normalised 0..1 across the domain
  int resolution = 256;           // samples along the longer side, 2..16384
};

// One area A_i sampled on its grid.
struct Slice {
  int axis = 0;             // the plane's normal axis (0: x = c1)
  int u_axis = 1, v_axis = 2; // the grid's horizontal and vertical index axes
  int nu = 2, nv = 2;       // k + 1, l + 1
  double c = 0.0;           // the plane's index position along axis
  Index3 lo, hi;            // the domain's index box
  std::vector<double> values; // nu * nv, u fastest, v upward from lo

  // Index position of grid point (iu, iv).
  Vec3d point(int iu, int iv) const;
  double value(int iu, int iv) const { return values[size_t(iv) * size_t(nu) + size_t(iu)]; }
};

// Samples the three slices. Axes: 0 -> (u, v) = (y, z), 1 -> (x, z),
// 2 -> (x, y). Throws InvalidArgument when a position lies outside the
// domain or the resolution is out of range.
std::array<Slice, 3> sample_slices(const ScalarGrid& grid, const Domain& domain,
                                   const SliceSettings& settings);

// The scale over the values of all three slices.
ColourScale slices_scale(const std::array<Slice, 3>& slices, const ColourSettings& colours);

// The slice as an image, v upward (row 0 is the top, v = nv - 1), with a
// colour bar on the right when asked.
Image slice_image(const Slice& slice, const ColourScale& scale, bool colour_bar);

enum class SliceKind { Plane = 0, Surface = 1, Curves = 2 };

// The slice as a mesh in world coordinates (see isoform_slice_mesh):
// height is the largest displacement of a graph as a fraction of the
// domain's largest world extent.
Mesh slice_mesh(const Slice& slice, const Domain& domain, const ColourScale& scale,
                SliceKind kind, double height);

// The 12 edges of the domain box, as black vertices and loose edges.
Mesh domain_outline(const Domain& domain);

}  // namespace isoform::visualize
