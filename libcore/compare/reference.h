// What a comparison measures deviation from: an analytic sphere or torus
// (exact distance and exact mean curvature), or a scalar grid's contour
// (the distance estimate |f(x) - iso| / |grad f| of the grid's trilinear
// interpolant, in voxels).
#pragma once

#include <memory>
#include <string>

#include "libcore/mesh.h"
#include "libcore/volume.h"

namespace isoform::compare {

class Reference {
 public:
  virtual ~Reference() = default;
  // Distance of world point p from the reference surface, >= 0, in unit().
  virtual double deviation(const Vec3d& p) const = 0;
  // The exact mean curvature of the reference at its point nearest to p
  // (outward normals: a sphere has 1/r), or NaN when unknown.
  virtual double mean_curvature(const Vec3d& p) const = 0;
  virtual std::string unit() const = 0;         // "world units" or "voxels"
  virtual std::string description() const = 0;  // "sphere centre (0, 0, 0) radius 1"
  virtual std::string kind() const = 0;         // "sphere", "torus", "volume"
};

std::unique_ptr<Reference> make_sphere_reference(const Vec3d& centre, double radius);
// A torus around the z axis through centre: tube radius minor around the
// circle of radius major.
std::unique_ptr<Reference> make_torus_reference(const Vec3d& centre, double major, double minor);
// The contour f = iso of grid, sampled over the index box that holds the
// mesh's vertices (with a margin). `what` names the grid in messages.
std::unique_ptr<Reference> make_volume_reference(const ScalarGrid& grid, double iso, const Mesh& mesh,
                                                 const std::string& what);

// Least-squares-free fits for when the caller gives no parameters: the
// area-weighted centroid of the triangles and their mean distance from it (sphere); the
// centroid, the mean distance from the z axis through it (major) and the
// mean distance from that circle (minor) (torus).
void fit_sphere(const Mesh& mesh, Vec3d& centre, double& radius);
void fit_torus(const Mesh& mesh, Vec3d& centre, double& major, double& minor);

}  // namespace isoform::compare
