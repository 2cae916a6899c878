// The domain-subdivision method of Section 2.2: q_x q_y q_z subvolumes
// V_rst separated by gaps, their faces Gouraud-coloured from the function
// at (k+1)(l+1) points per face; over the domain itself or over a volume
// given by a map from uvw-space (Figure 2.4: part of the unit ball).
#pragma once

#include <array>
#include <functional>

#include "../mesh.h"
#include "colour_scale.h"
#include "domain.h"

namespace isoform::visualize {

// One axis of the subdivision: x_r = x_min + r (1 + alpha) dx with
// dx = (x_max - x_min) / (q + alpha (q - 1)), r = 0 .. q - 1.
struct SubdivisionAxis {
  double min = 0.0, max = 1.0, alpha = 1.0;
  int q = 1;
  double delta() const { return (max - min) / (double(q) + alpha * double(q - 1)); }
  double start(int r) const { return min + double(r) * (1.0 + alpha) * delta(); }
};

// A volume in parameter space [lo, hi] and where its points lie: to_index
// gives the grid's index position (for the value), to_world the vertex.
struct ParameterMap {
  Vec3d lo, hi;
  std::function<Vec3d(const Vec3d&)> to_index;
  std::function<Vec3d(const Vec3d&)> to_world;
  bool flips = false;  // true when the map reverses orientation
};

// The domain itself: parameters are index positions.
ParameterMap box_map(const Domain& domain);
// (x, y, z) = centre + (u cos v, u sin v cos w, u sin v sin w), world units.
ParameterMap spherical_map(const Domain& domain, const Vec3d& uvw_lo, const Vec3d& uvw_hi,
                           const Vec3d& centre);

struct BoxSettings {
  std::array<int, 3> q{5, 5, 5};
  Vec3d gap{1, 1, 1};
  std::array<int, 2> face_cells{1, 1};  // k, l
  bool centroid_lines = false;
};

// The subvolumes as one mesh in world coordinates: per face (k+1)(l+1) own
// vertices with colours (alpha 255) and outward normals, 2 k l triangles,
// faces in the order -x, +x, -y, +y, -z, +z of each subvolume, subvolumes
// r fastest, then s, then t; parts = subvolume index. f_min and f_max are
// those of all face points (the corners when k = l = 1). Throws
// InvalidArgument for q < 1, a negative gap, k or l < 1, or a face point
// outside the grid's domain.
Mesh domain_boxes(const ScalarGrid& grid, const Domain& domain, const ParameterMap& map,
                  const BoxSettings& settings, const ColourSettings& colours);

}  // namespace isoform::visualize
