// The two inputs: a graph of Table 4.1 on a fine grid with the seed's
// triangulation, and a contour of the headsq CT scan resampled finely
// enough to give about a million triangles, made with isoform's C API.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "reduce_bench.h"
#include "tests/curvature/truth.h"

namespace isoform_reduce_bench {
namespace {

constexpr int kHeadDims[3] = {64, 64, 93};
constexpr double kHeadSpacing[3] = {3.2, 3.2, 1.5};

std::vector<float> read_headsq(const std::string& dir) {
  const std::string path = dir + "/headsq_64x64x93_u16le.raw";
  std::ifstream in(path, std::ios::binary);
  const size_t n = size_t(kHeadDims[0]) * kHeadDims[1] * kHeadDims[2];
  std::vector<uint16_t> raw(n);
  in.read(reinterpret_cast<char*>(raw.data()), std::streamsize(2 * n));
  if (!in) throw std::runtime_error("cannot read " + path + " (64x64x93 u16 little-endian)");
  return std::vector<float>(raw.begin(), raw.end());
}

// Trilinear samples of the scan on an isotropic grid of the given spacing
// over the same extent, with one layer of zeros around it so that the
// contour closes (the scan's own faces would otherwise leave it open).
std::vector<float> resample_padded(const std::vector<float>& scan, double spacing, std::array<int, 3>& dims) {
  std::array<std::vector<std::pair<int, double>>, 3> axis;
  for (int a = 0; a < 3; ++a) {
    const double extent = (kHeadDims[a] - 1) * kHeadSpacing[a];
    const int n = int(std::floor(extent / spacing)) + 1;
    for (int s = 0; s < n; ++s) {
      const double x = s * spacing / kHeadSpacing[a];
      const int lower = std::min(int(x), kHeadDims[a] - 2);
      axis[a].emplace_back(lower, x - lower);
    }
    dims[a] = n + 2;
  }
  const auto at = [&](int i, int j, int k) { return double(scan[(size_t(k) * kHeadDims[1] + j) * kHeadDims[0] + i]); };
  std::vector<float> out(size_t(dims[0]) * dims[1] * dims[2], 0.0f);
  for (size_t k = 0; k < axis[2].size(); ++k)
    for (size_t j = 0; j < axis[1].size(); ++j)
      for (size_t i = 0; i < axis[0].size(); ++i) {
        const auto [x, wx] = axis[0][i];
        const auto [y, wy] = axis[1][j];
        const auto [z, wz] = axis[2][k];
        double v = 0;
        for (int c = 0; c < 8; ++c) {
          const int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
          v += (dx ? wx : 1 - wx) * (dy ? wy : 1 - wy) * (dz ? wz : 1 - wz) * at(x + dx, y + dy, z + dz);
        }
        out[((k + 1) * dims[1] + j + 1) * dims[0] + i + 1] = float(v);
      }
  return out;
}

}  // namespace

Surface compact(const Surface& s) {
  std::vector<int32_t> index(s.vertex_count(), -1);
  Surface c;
  c.triangles.reserve(s.triangles.size());
  for (int32_t v : s.triangles) {
    if (index[size_t(v)] < 0) {
      index[size_t(v)] = int32_t(c.vertex_count());
      c.points.insert(c.points.end(), &s.points[3 * size_t(v)], &s.points[3 * size_t(v)] + 3);
    }
    c.triangles.push_back(index[size_t(v)]);
  }
  return c;
}

Input make_graph(const Options& o) {
  const auto& graphs = isoform::truth::table41_graphs();
  const auto g = std::find_if(graphs.begin(), graphs.end(), [&](const auto& x) { return x.name == o.graph; });
  if (g == graphs.end()) throw std::runtime_error("no Table 4.1 graph called " + o.graph);
  const isoform::Mesh m = isoform::truth::graph_mesh(*g, o.graph_knots);
  Input in;
  in.name = "graph";
  in.what = "z = " + g->formula + " (Table 4.1's " + g->name + ") on " + std::to_string(o.graph_knots) + " x " +
            std::to_string(o.graph_knots) + " knots over [-1, 1]^2, the seed's split of each quad";
  in.mesh.points = m.precise_points;
  in.mesh.triangles = m.triangles;
  in.height = g->f;
  in.facts = Json{{"function", g->name}, {"formula", g->formula}, {"knots", o.graph_knots}};
  return in;
}

Input make_contour(const Options& o) {
  std::array<int, 3> dims{};
  const std::vector<float> grid = resample_padded(read_headsq(o.data_dir), o.contour_spacing, dims);
  const double spacing[3] = {o.contour_spacing, o.contour_spacing, o.contour_spacing};
  const double origin[3] = {-o.contour_spacing, -o.contour_spacing, -o.contour_spacing};
  isoform_volume* volume = nullptr;
  check(isoform_volume_from_dense(grid.data(), dims[0], dims[1], dims[2], spacing, origin, "density",
                                  ISOFORM_CLASS_FOG, &volume),
        "isoform_volume_from_dense");
  isoform_contour_options co;
  isoform_contour_options_default(&co);
  co.auto_isovalue = 0;
  co.isovalue = o.contour_iso;
  isoform_mesh* mesh = nullptr;
  const isoform_status st = isoform_contour(volume, 0, &co, nullptr, &mesh);
  isoform_volume_free(volume);
  check(st, "isoform_contour");
  Input in;
  in.name = "contour";
  isoform_mesh_stats stats;
  check(isoform_mesh_stats_get(mesh, &stats), "isoform_mesh_stats_get");
  std::vector<float> points(3 * isoform_mesh_vertex_count(mesh));
  in.mesh.triangles.resize(3 * isoform_mesh_triangle_count(mesh));
  check(isoform_mesh_copy_points(mesh, points.data()), "isoform_mesh_copy_points");
  check(isoform_mesh_copy_triangles(mesh, in.mesh.triangles.data()), "isoform_mesh_copy_triangles");
  isoform_mesh_free(mesh);
  in.mesh.points.assign(points.begin(), points.end());
  char what[256];
  std::snprintf(what, sizeof what,
                "headsq (64x64x93 CT) resampled trilinearly to spacing %g (%dx%dx%d with a zero border), "
                "isoform_contour at %g (cells method)",
                o.contour_spacing, dims[0], dims[1], dims[2], o.contour_iso);
  in.what = what;
  in.facts = Json{{"spacing", o.contour_spacing}, {"isovalue", o.contour_iso}, {"dims", dims},
                  {"parts", stats.parts}, {"boundary_edges", stats.boundary_edges},
                  {"euler_characteristic", stats.euler_characteristic}};
  return in;
}

void prepare_reference(Input& in, const Options& o) {
  in.diagonal = bbox_diagonal(in.mesh.view());
  in.samples = sample_surface(in.mesh.view(), o.samples, 11);
  in.tree = std::make_unique<TriangleTree>(in.mesh.view());
  isoform_mesh* mesh = nullptr;
  check(isoform_mesh_from_arrays_f64(in.mesh.points.data(), in.mesh.vertex_count(), in.mesh.triangles.data(),
                                     in.mesh.triangle_count(), &mesh),
        "isoform_mesh_from_arrays_f64");
  isoform_mesh_stats_get(mesh, &in.stats);
  isoform_mesh_free(mesh);
}

void save_input(const Input& in, const std::string& path) {
  isoform_mesh* mesh = nullptr;
  check(isoform_mesh_from_arrays_f64(in.mesh.points.data(), in.mesh.vertex_count(), in.mesh.triangles.data(),
                                     in.mesh.triangle_count(), &mesh),
        "isoform_mesh_from_arrays_f64");
  const isoform_status st = isoform_mesh_save(mesh, path.c_str());
  isoform_mesh_free(mesh);
  check(st, ("isoform_mesh_save " + path).c_str());
}

}  // namespace isoform_reduce_bench
