// Dropping small parts of a mesh (see part_filter.h).
#include "part_filter.h"

#include <cmath>

#include "topology.h"

namespace isoform {

namespace {

// The entries of `per` (n per vertex) of the vertices kept, in order.
template <class T>
void keep_vertices(std::vector<T>& values, size_t per, const std::vector<int32_t>& new_index) {
  if (values.empty()) return;
  size_t out = 0;
  for (size_t v = 0; v < new_index.size(); ++v) {
    if (new_index[v] < 0) continue;
    for (size_t c = 0; c < per; ++c) values[out * per + c] = values[v * per + c];
    ++out;
  }
  values.resize(out * per);
}

}  // namespace

std::vector<double> part_volumes(const Mesh& mesh) {
  std::vector<double> volume(size_t(mesh.part_count), 0.0);
  std::vector<bool> closed(size_t(mesh.part_count), true);
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const size_t part = size_t(mesh.parts[t]);
    double p[3][3];
    for (int c = 0; c < 3; ++c) {
      if (mesh.neighbours[3 * t + size_t(c)] < 0) closed[part] = false;
      for (int a = 0; a < 3; ++a) p[c][a] = mesh.points[3 * size_t(mesh.triangles[3 * t + size_t(c)]) + size_t(a)];
    }
    // p0 · (p1 × p2) / 6: the signed volume of the tetrahedron to the origin.
    volume[part] += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
                     p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                     p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) /
                    6.0;
  }
  for (size_t part = 0; part < volume.size(); ++part) volume[part] = closed[part] ? std::fabs(volume[part]) : -1.0;
  return volume;
}

PartFilterResult filter_parts(Mesh& mesh, const PartFilter& filter) {
  if (mesh.parts.size() != mesh.triangle_count() || mesh.neighbours.size() != mesh.triangles.size())
    compute_topology(mesh);
  PartFilterResult result;
  result.parts_before = mesh.part_count;
  result.triangles_before = (long long)mesh.triangle_count();
  std::vector<long long> size(size_t(mesh.part_count), 0);
  for (int32_t part : mesh.parts) ++size[size_t(part)];
  const std::vector<double> volume = filter.min_volume > 0 ? part_volumes(mesh) : std::vector<double>();
  // Parts are numbered by size, largest first: the K largest are 0 to K - 1.
  std::vector<bool> keep(size.size());
  for (size_t part = 0; part < size.size(); ++part)
    keep[part] = size[part] >= filter.min_triangles && (filter.largest <= 0 || (long long)part < filter.largest) &&
                 (volume.empty() || volume[part] < 0 || volume[part] >= filter.min_volume);
  // Triangles of kept parts; vertices they (or loose edges) use.
  std::vector<int32_t> new_index(mesh.vertex_count(), -1);
  size_t kept = 0;
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (!keep[size_t(mesh.parts[t])]) continue;
    for (int c = 0; c < 3; ++c) mesh.triangles[3 * kept + size_t(c)] = mesh.triangles[3 * t + size_t(c)];
    ++kept;
  }
  mesh.triangles.resize(3 * kept);
  for (int32_t v : mesh.triangles) new_index[size_t(v)] = 0;
  for (int32_t v : mesh.edges) new_index[size_t(v)] = 0;
  int32_t next = 0;
  for (int32_t& v : new_index)
    if (v == 0) v = next++;
  for (int32_t& v : mesh.triangles) v = new_index[size_t(v)];
  for (int32_t& v : mesh.edges) v = new_index[size_t(v)];
  keep_vertices(mesh.points, 3, new_index);
  keep_vertices(mesh.precise_points, 3, new_index);
  keep_vertices(mesh.normals, 3, new_index);
  keep_vertices(mesh.colors, 4, new_index);
  VertexCurvature& c = mesh.curvature;
  for (std::vector<float>* values : {&c.k1, &c.k2, &c.mean, &c.gauss, &c.absolute}) keep_vertices(*values, 1, new_index);
  keep_vertices(c.d1, 3, new_index);
  keep_vertices(c.d2, 3, new_index);
  if (!c.flags.empty()) {
    keep_vertices(c.flags, 1, new_index);
    const CurvatureMethod method = c.stats.method;
    c.stats = CurvatureStats{};
    c.stats.method = method;
    count_curvature_flags(c);
  }
  compute_topology(mesh);
  result.parts_after = mesh.part_count;
  result.triangles_after = (long long)mesh.triangle_count();
  return result;
}

}  // namespace isoform
