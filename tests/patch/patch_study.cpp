// patch_study: the figures of docs/patch.md. Figure 6.7 (the tetrahedron in
// the unit sphere: maximum and RMS distance for automatic and lower weights)
// and the two blends compared on coarse analytic meshes and real contours:
// reversed normals inside patches, how fast the normal turns next to the
// edges against inside, and distance from the true surface where known.
//
// usage: patch_study [SHARED_DATA_DIR]   (markdown on stdout)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "libcore/contour/contour.h"
#include "libcore/patch/side_vertex_surface.h"
#include "libcore/topology.h"
#include "patch_fixtures.h"
#include "vdbio/vdb_file.h"

namespace isoform::patch {
namespace {

using Distance = std::function<double(const V3d&)>;  // signed distance to the true surface

struct BlendFigures {
  double reversed = 0.0;      // fraction of interior samples with a reversed normal
  double edge_turn = 0.0;     // mean normal turn per unit barycentric distance, 0..0.02 from edges
  double inner_turn = 0.0;    // the same from 0.1 to 0.3
  double max_turn = 0.0;      // largest turn rate next to an edge
  double rms_distance = 0.0;  // from the true surface (NaN when unknown)
  double max_distance = 0.0;
};

V3d normal_at(const SideVertexSurface& s, size_t t, double u, double v, bool& ok) {
  SurfaceSample x;
  ok = s.evaluate_order(t, u, v, x, false);
  return V3d::from(x.normal);
}

double angle(const V3d& a, const V3d& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

// Along the median from the middle of edge i toward vertex i, turn of the
// normal between barycentric distances a and b from the edge, per unit.
double turn_rate(const SideVertexSurface& s, size_t t, int i, double along, double a, double b) {
  auto at = [&](double d) {
    double bary[3];
    bary[i] = d;
    bary[(i + 1) % 3] = (1 - d) * (1 - along);
    bary[(i + 2) % 3] = (1 - d) * along;
    bool ok = false;
    const V3d n = normal_at(s, t, bary[1], bary[2], ok);
    return n;
  };
  return angle(at(a), at(b)) / (b - a);
}

BlendFigures measure(const SideVertexSurface& s, const Distance& distance) {
  BlendFigures f;
  const int n = 12;
  long interior = 0, reversed = 0, edge_count = 0, dist_count = 0;
  double dist_sum = 0.0;
  // NOTE: large contours are measured on every stride-th triangle (about
  // 20,000 of them), which keeps the study to seconds.
  const size_t stride = std::max<size_t>(1, s.triangle_count() / 20000);
  for (size_t t = 0; t < s.triangle_count(); t += stride) {
    V3d data[3];
    for (int k = 0; k < 3; ++k) data[k] = s.vertex_normal(size_t(s.triangle_vertex(t, k)));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const double u = double(i) / n, v = double(j) / n;
        SurfaceSample x;
        if (!s.evaluate_order(t, u, v, x, false)) continue;
        if (distance) {
          const double d = distance(V3d::from(x.point));
          dist_sum += d * d;
          f.max_distance = std::max(f.max_distance, std::abs(d));
          ++dist_count;
        }
        if (i == 0 || j == 0 || i + j == n) continue;
        const V3d blend = (1 - u - v) * data[0] + u * data[1] + v * data[2];
        ++interior;
        if (dot(V3d::from(x.normal), blend) < 0.0) ++reversed;
      }
    for (int e = 0; e < 3; ++e)
      for (double along : {0.25, 0.5, 0.75}) {
        const double near = turn_rate(s, t, e, along, 0.0, 0.02), inner = turn_rate(s, t, e, along, 0.1, 0.3);
        f.edge_turn += near;
        f.inner_turn += inner;
        f.max_turn = std::max(f.max_turn, near);
        ++edge_count;
      }
  }
  f.reversed = interior ? double(reversed) / double(interior) : 0.0;
  f.edge_turn /= double(edge_count);
  f.inner_turn /= double(edge_count);
  f.rms_distance = dist_count ? std::sqrt(dist_sum / double(dist_count)) : NAN;
  if (!dist_count) f.max_distance = NAN;
  return f;
}

// A coarse torus (major radius 1, minor 0.4) of nu x nv quads split in two,
// with its exact normals.
Mesh torus(int nu, int nv) {
  Mesh m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double a = 2 * M_PI * i / nu, b = 2 * M_PI * j / nv;
      const double nx = std::cos(a) * std::cos(b), ny = std::sin(a) * std::cos(b), nz = std::sin(b);
      const double p[3] = {std::cos(a) + 0.4 * nx, std::sin(a) + 0.4 * ny, 0.4 * nz};
      for (int k = 0; k < 3; ++k) m.precise_points.push_back(p[k]);
      m.normals.push_back(float(nx));
      m.normals.push_back(float(ny));
      m.normals.push_back(float(nz));
    }
  m.points.assign(m.precise_points.begin(), m.precise_points.end());
  auto id = [&](int i, int j) { return int32_t(((i + nu) % nu) * nv + (j + nv) % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const int32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
    }
  compute_topology(m);
  return m;
}

double torus_distance(const V3d& p) {
  const double r = std::sqrt(p.x * p.x + p.y * p.y);
  return std::sqrt((r - 1) * (r - 1) + p.z * p.z) - 0.4;
}

// An icosphere: the icosahedron with each triangle split into four, points
// and normals on the unit sphere, `levels` times.
Mesh icosphere(int levels) {
  Mesh m = test::icosahedron();
  for (int l = 0; l < levels; ++l) {
    std::vector<double> p = m.precise_points;
    std::vector<int32_t> tris;
    std::map<std::pair<int32_t, int32_t>, int32_t> mid;
    auto middle = [&](int32_t a, int32_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      V3d q(p[3 * a] + p[3 * b], p[3 * a + 1] + p[3 * b + 1], p[3 * a + 2] + p[3 * b + 2]);
      q = unit(q);
      p.insert(p.end(), {q.x, q.y, q.z});
      return mid[key] = int32_t(p.size() / 3 - 1);
    };
    for (size_t t = 0; t < m.triangle_count(); ++t) {
      const int32_t a = m.triangles[3 * t], b = m.triangles[3 * t + 1], c = m.triangles[3 * t + 2];
      const int32_t ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      tris.insert(tris.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    m.precise_points = p;
    m.triangles = tris;
  }
  m.points.assign(m.precise_points.begin(), m.precise_points.end());
  m.normals = m.points;
  compute_topology(m);
  return m;
}

Mesh contour_file(const std::string& path) {
  const auto file = vdbio::open_vdb(path);
  ContourOptions o;
  o.isovalue = 0.0;
  o.auto_isovalue = false;
  return contour(*file->load(0), o, Progress(nullptr));
}

void figure_67() {
  std::printf("## Figure 6.7: the tetrahedron in the unit sphere\n\n");
  std::printf("Distance from the unit sphere over a barycentric grid of 60 steps per edge (1891 samples per face).\n\n");
  std::printf("| omega | blend | max distance | RMS distance | face centre radius | edge midpoint radius |\n|---|---|---|---|---|---|\n");
  for (double w : {0.0, 0.4, 0.2, 0.1})
    for (Blend b : {Blend::Squared, Blend::Printed}) {
      PatchOptions o;
      o.tension = w;
      o.blend = b;
      const SideVertexSurface s(test::tetrahedron(), o);
      double sum = 0, worst = 0;
      long count = 0;
      const int n = 60;
      for (size_t t = 0; t < 4; ++t)
        for (int i = 0; i <= n; ++i)
          for (int j = 0; i + j <= n; ++j) {
            V3d p;
            s.point(t, double(i) / n, double(j) / n, p);
            const double d = 1 - norm(p);
            sum += d * d;
            worst = std::max(worst, std::abs(d));
            ++count;
          }
      V3d c, e;
      s.point(0, 1.0 / 3, 1.0 / 3, c);
      s.point(0, 0.5, 0.0, e);
      std::printf("| %s | %s | %.5f | %.5f | %.5f | %.5f |\n", w == 0 ? "auto (0.577)" : std::to_string(w).substr(0, 3).c_str(),
                  b == Blend::Squared ? "squared" : "printed", worst, std::sqrt(sum / count), norm(c), norm(e));
    }
  std::printf("\n");
}

void blends(const std::string& name, const Mesh& m, const Distance& d) {
  for (Blend b : {Blend::Squared, Blend::Printed}) {
    PatchOptions o;
    o.blend = b;
    const SideVertexSurface s(m, o);
    const BlendFigures f = measure(s, d);
    std::fflush(stdout);
    std::printf("| %s | %zu | %s | %.4f%% | %.3f | %.3f | %.2f | %.3f | %s | %s |\n", name.c_str(), m.triangle_count(),
                b == Blend::Squared ? "squared" : "printed", 100 * f.reversed, f.edge_turn, f.inner_turn,
                f.edge_turn / f.inner_turn, f.max_turn,
                std::isnan(f.rms_distance) ? "-" : std::to_string(f.rms_distance).substr(0, 8).c_str(),
                std::isnan(f.max_distance) ? "-" : std::to_string(f.max_distance).substr(0, 8).c_str());
  }
}

}  // namespace
}  // namespace isoform::patch

int main(int argc, char** argv) {
  using namespace isoform::patch;
  figure_67();
  std::printf("## The two blends\n\n");
  std::printf("Normal turn rates are radians per unit barycentric distance along the medians, at 1/4, 1/2 "
              "and 3/4 of each edge: next to the edge (0 to 0.02) and inside (0.1 to 0.3). Reversed: interior "
              "samples (12 steps per edge) whose exact normal points against the blended data normals.\n\n");
  std::printf("| mesh | triangles | blend | reversed | edge turn | inner turn | edge/inner | max edge turn | RMS distance | max distance |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  auto sphere = [](const V3d& p) { return norm(p) - 1.0; };
  blends("tetrahedron", test::tetrahedron(), sphere);
  blends("icosahedron", test::icosahedron(), sphere);
  blends("icosphere 1", icosphere(1), sphere);
  blends("torus 8x4", torus(8, 4), torus_distance);
  blends("torus 16x8", torus(16, 8), torus_distance);
  blends("skewed octahedron", test::skewed_octahedron(), nullptr);
  if (argc > 1) {
    const std::string dir = argv[1];
    for (const char* f : {"sphere.vdb", "cube.vdb"}) {
      const std::string path = dir + "/" + f;
      if (!std::filesystem::exists(path)) continue;
      blends(std::string(f) + " contour", contour_file(path), nullptr);
    }
  }
  return 0;
}
