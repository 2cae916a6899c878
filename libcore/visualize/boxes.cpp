// Section 2.2, domain subdivision: subvolume corners, face grids, colours.
#include "boxes.h"

#include <cmath>
#include <string>

#include "../errors.h"
#include "mesh_build.h"

namespace isoform::visualize {
namespace {

void check_settings(const Domain& domain, const BoxSettings& s) {
  for (int a = 0; a < 3; ++a) {
    if (s.q[a] < 1)
      throw InvalidArgument(domain.what + ": subvolumes per axis q = " + std::to_string(s.q[a]) +
                            " along " + "xyz"[a] + "; q must be 1 or more");
    if (!(s.gap[a] >= 0.0) || !std::isfinite(s.gap[a]))
      throw InvalidArgument(domain.what + ": gap ratio " + std::to_string(s.gap[a]) + " along " +
                            "xyz"[a] + " must be 0 or more");
  }
  if (s.face_cells[0] < 1 || s.face_cells[1] < 1 || s.face_cells[0] > 1024 || s.face_cells[1] > 1024)
    throw InvalidArgument(domain.what + ": points per face need k, l in 1..1024");
}

// One face of a subvolume: fixed axis `axis` at parameter `at`, spanning
// [lo, hi] on the other two axes (u = next axis, v = the one after).
struct Face {
  int axis;
  bool upper;  // the +axis face
  Vec3d lo, hi;
};

// The face's (k+1)(l+1) parameter points, u fastest.
std::vector<Vec3d> face_points(const Face& face, int k, int l) {
  const int u = (face.axis + 1) % 3, v = (face.axis + 2) % 3;
  std::vector<Vec3d> out;
  for (int j = 0; j <= l; ++j)
    for (int i = 0; i <= k; ++i) {
      Vec3d p;
      p[face.axis] = face.upper ? face.hi[face.axis] : face.lo[face.axis];
      p[u] = face.lo[u] + (face.hi[u] - face.lo[u]) * double(i) / double(k);
      p[v] = face.lo[v] + (face.hi[v] - face.lo[v]) * double(j) / double(l);
      out.push_back(p);
    }
  return out;
}

struct FaceSamples {
  Face face;
  std::vector<Vec3d> world;
  std::vector<double> values;
  int32_t box;
};

}  // namespace

ParameterMap box_map(const Domain& domain) {
  ParameterMap m;
  for (int a = 0; a < 3; ++a) {
    m.lo[a] = domain.lo[a];
    m.hi[a] = domain.hi[a];
  }
  m.to_index = [](const Vec3d& p) { return p; };
  const Affine t = domain.to_world;
  m.to_world = [t](const Vec3d& p) { return t.apply(p); };
  m.flips = t.determinant() < 0;
  return m;
}

ParameterMap spherical_map(const Domain& domain, const Vec3d& uvw_lo, const Vec3d& uvw_hi,
                           const Vec3d& centre) {
  ParameterMap m;
  m.lo = uvw_lo;
  m.hi = uvw_hi;
  m.to_world = [centre](const Vec3d& p) {
    return Vec3d{centre[0] + p[0] * std::cos(p[1]), centre[1] + p[0] * std::sin(p[1]) * std::cos(p[2]),
                 centre[2] + p[0] * std::sin(p[1]) * std::sin(p[2])};
  };
  const Domain d = domain;
  auto world = m.to_world;
  m.to_index = [d, world](const Vec3d& p) { return d.index(world(p)); };
  // The Jacobian determinant is u^2 sin v: orientation is kept for u >= 0
  // and v in [0, pi], as in Figure 2.4.
  m.flips = false;
  return m;
}

Mesh domain_boxes(const ScalarGrid& grid, const Domain& domain, const ParameterMap& map,
                  const BoxSettings& s, const ColourSettings& colours) {
  check_settings(domain, s);
  SubdivisionAxis axes[3];
  for (int a = 0; a < 3; ++a) axes[a] = {map.lo[a], map.hi[a], s.gap[a], s.q[a]};
  const SampleRegion region(grid, domain.lo, domain.hi);
  // Phase 1: every face's points and values, so that f_min and f_max are
  // known before any colour is assigned.
  std::vector<FaceSamples> faces;
  std::vector<double> all;
  for (int t = 0; t < s.q[2]; ++t)
    for (int r_s = 0; r_s < s.q[1]; ++r_s)
      for (int r = 0; r < s.q[0]; ++r) {
        const int idx[3] = {r, r_s, t};
        Vec3d lo, hi;
        for (int a = 0; a < 3; ++a) {
          lo[a] = axes[a].start(idx[a]);
          hi[a] = lo[a] + axes[a].delta();
        }
        for (int f = 0; f < 6; ++f) {
          FaceSamples fs{{f / 2, f % 2 == 1, lo, hi}, {}, {}, int32_t((t * s.q[1] + r_s) * s.q[0] + r)};
          for (const Vec3d& p : face_points(fs.face, s.face_cells[0], s.face_cells[1])) {
            const Vec3d index = map.to_index(p);
            domain.require_inside(index, "a subvolume point");
            fs.world.push_back(map.to_world(p));
            fs.values.push_back(region.trilinear(index));
          }
          all.insert(all.end(), fs.values.begin(), fs.values.end());
          faces.push_back(std::move(fs));
        }
      }
  const ColourScale scale = make_scale(colours, all);
  // Phase 2: the mesh. (u, v) = (axis + 1, axis + 2) is right-handed, so the
  // grid's counter-clockwise triangles face +axis: flip the lower faces.
  Mesh mesh;
  std::vector<Vec3d> centroids;
  for (const FaceSamples& fs : faces) {
    Mesh face;
    for (size_t i = 0; i < fs.world.size(); ++i) {
      const Rgb c = scale.colour(fs.values[i]);
      add_vertex(face, fs.world[i], {c[0], c[1], c[2], 255});
    }
    add_grid_triangles(face, 0, s.face_cells[0] + 1, s.face_cells[1] + 1, fs.face.upper == map.flips);
    Vec3d fallback{0, 0, 0};
    fallback[fs.face.axis] = fs.face.upper ? 1.0 : -1.0;
    compute_vertex_normals(face, fallback);
    append_mesh(mesh, face);
    mesh.parts.insert(mesh.parts.end(), face.triangle_count(), fs.box);
    if (fs.face.axis == 0 && !fs.face.upper) {
      Vec3d mid;
      for (int a = 0; a < 3; ++a) mid[a] = 0.5 * (fs.face.lo[a] + fs.face.hi[a]);
      centroids.push_back(map.to_world(mid));
    }
  }
  mesh.part_count = s.q[0] * s.q[1] * s.q[2];
  if (s.centroid_lines) {
    // Centroids as extra vertices, joined to the next subvolume along each axis.
    const int32_t first = int32_t(mesh.vertex_count());
    for (const Vec3d& c : centroids) {
      add_vertex(mesh, c, {0, 0, 0, 255});
      mesh.normals.insert(mesh.normals.end(), {0.0f, 0.0f, 1.0f});
    }
    const int32_t step[3] = {1, s.q[0], s.q[0] * s.q[1]};
    for (int t = 0; t < s.q[2]; ++t)
      for (int r_s = 0; r_s < s.q[1]; ++r_s)
        for (int r = 0; r < s.q[0]; ++r) {
          const int idx[3] = {r, r_s, t};
          const int32_t b = (t * s.q[1] + r_s) * s.q[0] + r;
          for (int a = 0; a < 3; ++a)
            if (idx[a] + 1 < s.q[a]) mesh.edges.insert(mesh.edges.end(), {first + b, first + b + step[a]});
        }
  }
  return mesh;
}

}  // namespace isoform::visualize
