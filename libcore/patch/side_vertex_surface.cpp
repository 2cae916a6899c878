// The side-vertex surface of Hamann (1991), Chapter 6: input checks, the
// shared edge curves, and evaluation with exact derivatives (jet.h).
#include "side_vertex_surface.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <type_traits>

#include "../errors.h"
#include "fast_eval.h"
#include "orientation.h"
#include "patch_eval.h"

namespace isoform::patch {
namespace {

std::string vertex_name(size_t i) { return "vertex " + std::to_string(i); }

std::vector<V3d> read_points(const Mesh& mesh) {
  const size_t n = mesh.vertex_count();
  const bool precise = mesh.precise_points.size() == 3 * n;
  std::vector<V3d> p(n);
  for (size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      const double c = precise ? mesh.precise_points[3 * i + a] : double(mesh.points[3 * i + a]);
      if (!std::isfinite(c)) throw InvalidArgument("side-vertex surface: " + vertex_name(i) + " is not finite");
    }
    p[i] = precise ? V3d(mesh.precise_points[3 * i], mesh.precise_points[3 * i + 1], mesh.precise_points[3 * i + 2])
                   : V3d(mesh.points[3 * i], mesh.points[3 * i + 1], mesh.points[3 * i + 2]);
  }
  return p;
}

// Unit normals; refuses missing, zero and non-finite ones.
std::vector<V3d> read_normals(const Mesh& mesh) {
  const size_t n = mesh.vertex_count();
  if (mesh.normals.size() != 3 * n)
    throw InvalidArgument("side-vertex surface: the mesh has no vertex normals (the patch interpolates them)");
  std::vector<V3d> out(n);
  for (size_t i = 0; i < n; ++i) {
    const V3d q(mesh.normals[3 * i], mesh.normals[3 * i + 1], mesh.normals[3 * i + 2]);
    const double len = norm(q);
    if (!std::isfinite(len) || !(len > 1e-12))
      throw InvalidArgument("side-vertex surface: the normal of " + vertex_name(i) + " is zero or not finite");
    out[i] = (1.0 / len) * q;
  }
  return out;
}

void check_triangles(const Mesh& mesh, const std::vector<V3d>& points) {
  const size_t n = points.size();
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const int32_t* v = &mesh.triangles[3 * t];
    for (int i = 0; i < 3; ++i)
      if (v[i] < 0 || size_t(v[i]) >= n)
        throw InvalidArgument("side-vertex surface: triangle " + std::to_string(t) + " refers to vertex " +
                              std::to_string(v[i]) + " of " + std::to_string(n));
    for (int i = 0; i < 3; ++i) {
      const int32_t a = v[i], b = v[(i + 1) % 3];
      if (a == b || norm(points[size_t(a)] - points[size_t(b)]) == 0.0)
        throw InvalidArgument("side-vertex surface: triangle " + std::to_string(t) + " is degenerate: " +
                              vertex_name(size_t(a)) + " and " + vertex_name(size_t(b)) + " coincide");
    }
  }
}

double inverse_weight(double omega, const std::string& what) {
  if (!std::isfinite(omega) || omega < 0.0)
    throw InvalidArgument("side-vertex surface: " + what + " must be 0 (automatic) or a positive weight, not " +
                          std::to_string(omega));
  return omega == 0.0 ? 0.0 : 1.0 / omega;
}

uint64_t edge_key(int32_t a, int32_t b) {
  return (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b));
}

template <bool S>
std::array<double, 3> as_array(const V3<Jet<S>>& p, int part, int index) {
  auto pick = [&](const Jet<S>& j) { return part == 0 ? j.v : (part == 1 ? j.d[index] : j.h[index]); };
  return {pick(p.x), pick(p.y), pick(p.z)};
}

bool finite(const std::array<double, 3>& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

}  // namespace

SideVertexSurface::SideVertexSurface(const Mesh& mesh, const PatchOptions& options) : options_(options) {
  if (options.blend != Blend::Printed && options.blend != Blend::Squared)
    throw InvalidArgument("side-vertex surface: unknown blend");
  inv_tension_ = inverse_weight(options.tension, "the tension");
  points_ = read_points(mesh);
  normals_ = read_normals(mesh);
  check_triangles(mesh, points_);
  triangles_ = mesh.triangles;
  build_edges(options.edge_tension);
  for (size_t t = 0; t < triangle_count(); ++t) stats_.inverted_triangles += inverted_triangle(*this, t) ? 1 : 0;
}

// One curve per unordered vertex pair, lower index first; triangles keep
// which of their edges runs against it.
void SideVertexSurface::build_edges(const std::vector<EdgeTension>& tension) {
  const size_t m = triangle_count();
  std::vector<std::pair<uint64_t, uint32_t>> keys(3 * m);
  for (size_t t = 0; t < m; ++t)
    for (int i = 0; i < 3; ++i)
      keys[3 * t + i] = {edge_key(triangles_[3 * t + (i + 1) % 3], triangles_[3 * t + (i + 2) % 3]),
                         uint32_t(3 * t + i)};
  std::sort(keys.begin(), keys.end());
  triangle_edges_.assign(3 * m, {});
  for (size_t k = 0; k < keys.size(); ++k) {
    if (k == 0 || keys[k].first != keys[k - 1].first) {
      edge_vertices_.push_back(int32_t(keys[k].first >> 32));
      edge_vertices_.push_back(int32_t(keys[k].first & 0xffffffffu));
    }
    const size_t slot = keys[k].second, base = slot - slot % 3;
    const int32_t from = triangles_[base + (slot % 3 + 1) % 3], to = triangles_[base + (slot % 3 + 2) % 3];
    triangle_edges_[slot] = {int32_t(edge_vertices_.size() / 2 - 1), from > to};
  }
  const size_t edges = edge_vertices_.size() / 2;
  edge_inv_tension_.assign(edges, inv_tension_);
  if (!tension.empty()) {
    std::map<uint64_t, size_t> index;
    for (size_t e = 0; e < edges; ++e) index[edge_key(edge_vertices_[2 * e], edge_vertices_[2 * e + 1])] = e;
    for (const EdgeTension& et : tension) {
      const auto it = index.find(edge_key(et.a, et.b));
      const std::string name = "the weight of edge " + std::to_string(et.a) + "-" + std::to_string(et.b);
      if (it == index.end()) throw InvalidArgument("side-vertex surface: " + name + ": no such edge in the mesh");
      if (!(et.omega > 0.0)) throw InvalidArgument("side-vertex surface: " + name + " must be positive");
      edge_inv_tension_[it->second] = inverse_weight(et.omega, name);
    }
  }
  curves_.resize(edges);
  stats_.edges = (long long)edges;
  for (size_t e = 0; e < edges; ++e) {
    const size_t a = size_t(edge_vertices_[2 * e]), b = size_t(edge_vertices_[2 * e + 1]);
    curves_[e] = make_edge_curve(points_[a], normals_[a], points_[b], normals_[b], edge_inv_tension_[e]);
    const uint8_t f = curves_[e].conic.flags;
    stats_.nonconvex_edges += (f & kConicNonConvex) ? 1 : 0;
    stats_.opposite_normal_edges += (f & kConicOppositeNormals) ? 1 : 0;
    stats_.fallback_plane_edges += (f & kConicFallbackPlane) ? 1 : 0;
  }
  polys_.resize(edges);
  end_derivatives_.resize(2 * edges);
  for (size_t e = 0; e < edges; ++e) {
    polys_[e] = make_edge_poly(curves_[e]);
    end_derivatives_[2 * e] = conic_eval(curves_[e].conic, 0.0).tangent;
    end_derivatives_[2 * e + 1] = conic_eval(curves_[e].conic, 1.0).tangent;
  }
}

bool SideVertexSurface::point(size_t triangle, double u, double v, V3d& out) const {
  if (triangle >= triangle_count() || !(u >= 0.0) || !(v >= 0.0) || !(u + v <= 1.0 + 1e-12)) return false;
  if (!patch_point(*this, triangle, u, v, out)) {
    // A corner: the nearest vertex.
    const int i = (u < 0.5 && v < 0.5) ? 0 : (u >= v ? 1 : 2);
    out = points_[size_t(triangles_[3 * triangle + i])];
  }
  return std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.z);
}

namespace {

// d/ds of the surface along the edge from local vertex p to local vertex q,
// at p (s = 0, weight s on q): there the surface is the edge's curve.
V3d edge_derivative(const SideVertexSurface& s, size_t tri, int p, int q) {
  const TriangleEdge te = s.triangle_edge(tri, 3 - p - q);
  const bool forward = s.triangle_vertex(tri, q) > s.triangle_vertex(tri, p);
  const V3d& d = s.edge_end_derivative(size_t(te.edge), forward ? 0 : 1);
  return forward ? d : -d;
}

template <bool S>
void fill(const V3<Jet<S>>& p, SurfaceSample& out) {
  out.point = as_array(p, 0, 0);
  out.du = as_array(p, 1, 0);
  out.dv = as_array(p, 1, 1);
  out.has_second = S;
  if constexpr (S) {
    out.duu = as_array(p, 2, 0);
    out.duv = as_array(p, 2, 1);
    out.dvv = as_array(p, 2, 2);
  } else {
    out.duu = out.duv = out.dvv = {0.0, 0.0, 0.0};
  }
}

// The unit of du x dv, or false where it vanishes.
bool set_normal(SurfaceSample& out) {
  const V3d n = cross(V3d::from(out.du), V3d::from(out.dv));
  const double len = norm(n);
  if (!(len > 1e-300) || !std::isfinite(len)) return false;
  out.normal = {n.x / len, n.y / len, n.z / len};
  return true;
}

}  // namespace

// At vertex i: the vertex, its normal, and first derivatives from the two
// boundary curves that leave it (the weights (6.2) are 0/0 there).
bool SideVertexSurface::corner(size_t tri, int i, SurfaceSample& out) const {
  const size_t vi = size_t(triangles_[3 * tri + i]);
  V3d du, dv;
  if (i == 0) {
    du = edge_derivative(*this, tri, 0, 1);
    dv = edge_derivative(*this, tri, 0, 2);
  } else if (i == 1) {
    du = -edge_derivative(*this, tri, 1, 0);
    dv = edge_derivative(*this, tri, 1, 2) + du;
  } else {
    dv = -edge_derivative(*this, tri, 2, 0);
    du = edge_derivative(*this, tri, 2, 1) + dv;
  }
  const V3d& p = points_[vi];
  out.point = {p.x, p.y, p.z};
  out.du = {du.x, du.y, du.z};
  out.dv = {dv.x, dv.y, dv.z};
  out.duu = out.duv = out.dvv = {0.0, 0.0, 0.0};
  out.has_second = false;
  // The data normal (exact interpolation), turned to the triangle's side.
  V3d side = cross(du, dv);
  if (!(norm(side) > 0.0)) {
    const V3d& a = points_[size_t(triangles_[3 * tri])];
    side = cross(points_[size_t(triangles_[3 * tri + 1])] - a, points_[size_t(triangles_[3 * tri + 2])] - a);
  }
  const V3d n = dot(normals_[vi], side) < 0.0 ? -normals_[vi] : normals_[vi];
  out.normal = {n.x, n.y, n.z};
  return finite(out.du) && finite(out.dv);
}

bool SideVertexSurface::evaluate(size_t tri, double u, double v, SurfaceSample& out) const {
  return evaluate_order(tri, u, v, out, options_.second_derivatives);
}

// `eval(bool_constant<S>, p)` fills p with the point as jets, false at a
// corner.
template <class Eval>
bool SideVertexSurface::evaluate_with(size_t tri, double u, double v, SurfaceSample& out, bool second,
                                      Eval eval) const {
  if (tri >= triangle_count() || !(u >= 0.0) || !(v >= 0.0) || !(u + v <= 1.0 + 1e-12)) return false;
  bool inside = false;
  if (second) {
    V3<Jet<true>> p;
    inside = eval(std::true_type{}, p);
    if (inside) fill(p, out);
  } else {
    V3<Jet<false>> p;
    inside = eval(std::false_type{}, p);
    if (inside) fill(p, out);
  }
  if (!inside) return corner(tri, (u < 0.5 && v < 0.5) ? 0 : (u >= v ? 1 : 2), out);
  if (!finite(out.point) || !finite(out.du) || !finite(out.dv)) return false;
  if (out.has_second && (!finite(out.duu) || !finite(out.duv) || !finite(out.dvv))) return false;
  return set_normal(out);
}

bool SideVertexSurface::evaluate_order(size_t tri, double u, double v, SurfaceSample& out, bool second) const {
  return evaluate_with(tri, u, v, out, second, [&](auto order, auto& p) {
    return fast::patch_point<decltype(order)::value>(*this, tri, u, v, p);
  });
}

bool SideVertexSurface::evaluate_reference(size_t tri, double u, double v, SurfaceSample& out, bool second) const {
  return evaluate_with(tri, u, v, out, second, [&](auto order, auto& p) {
    constexpr bool S = decltype(order)::value;
    return patch_point(*this, tri, Jet<S>::variable(u, 0), Jet<S>::variable(v, 1), p);
  });
}

std::unique_ptr<TriangleSurface> make_side_vertex_surface(const Mesh& mesh, const PatchOptions& options,
                                                          std::string& error) {
  try {
    error.clear();
    return std::make_unique<SideVertexSurface>(mesh, options);
  } catch (const std::exception& e) {
    error = e.what();
    return nullptr;
  }
}

}  // namespace isoform::patch
