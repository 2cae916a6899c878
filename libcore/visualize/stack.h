// The transparency method of Section 2.2: three sets of rectangles, parallel
// to the xy-, xz- and yz-planes of an (n_x+1)(n_y+1)(n_z+1) grid over the
// domain, coloured by the function at their corners with alpha = 1 - t, and
// sorted "with respect to their distance to the screen", back to front.
#pragma once

#include <array>

#include "../mesh.h"
#include "colour_scale.h"
#include "domain.h"

namespace isoform::visualize {

struct StackSettings {
  std::array<int, 3> n{8, 8, 8};
  double transparency = 0.5;  // t: c_new = (1 - t) c_poly + t c_old
  Vec3d view{-1, -1, -1};     // world direction from the eye into the scene
};

// Depth of a world point along the view direction (larger is farther).
double depth(const Vec3d& p, const Vec3d& view);

// The rectangles as one mesh in world coordinates: rectangle r is vertices
// 4r .. 4r + 3 and triangles 2r, 2r + 1, ordered so that the key of each
// rectangle (the depth of its corner nearest the eye, the seed's criterion)
// never increases; equal keys keep the order xy, xz, yz sets, then grid
// order. Normals face the eye. Throws InvalidArgument for n < 1, t outside
// [0, 1] or a zero view direction.
Mesh transparency_stack(const ScalarGrid& grid, const Domain& domain, const StackSettings& settings,
                        const ColourSettings& colours);

}  // namespace isoform::visualize
