// Building the working structure of the reduction and writing its result back.
#include "work_mesh.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "../topology.h"
#include "queue.h"

namespace isoform::reduce {
namespace {

// A vertex is on the boundary when one of its edges has one triangle: with
// consistent orientation, a directed edge v->x without its reverse x->v.
bool is_on_boundary(const WorkMesh& w, int v) {
  for (int f : w.vfaces[size_t(v)]) {
    const int i = w.face_with_vertex_index(f, v);
    const int next = w.tri[size_t(f)][size_t((i + 1) % 3)];
    bool reverse = false;
    for (int g : w.vfaces[size_t(v)]) {
      const int j = w.face_with_vertex_index(g, v);
      if (w.tri[size_t(g)][size_t((j + 2) % 3)] == next) reverse = true;
    }
    if (!reverse) return true;
  }
  return false;
}

// Each vertex's faces in ascending order, from the star table.
void fill_face_lists(WorkMesh& w, const VertexStars& stars) {
  const size_t nv = w.pos.size();
  w.vfaces.reset(nv);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nv, 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t v = r.begin(); v != r.end(); ++v)
      for (const int32_t* f = stars.begin(v); f != stars.end(v); ++f) w.vfaces.push_back(v, int(*f));
  });
}

}  // namespace

WorkMesh build_work_mesh(const Mesh& mesh, const VertexCurvature& c, const VertexStars& stars,
                         const std::vector<uint8_t>& on_boundary) {
  WorkMesh w;
  const size_t nv = mesh.vertex_count(), nt = mesh.triangle_count();
  const bool precise = mesh.precise_points.size() == 3 * nv;
  w.pos.resize(nv);
  tbb::parallel_for(size_t(0), nv, [&](size_t v) {
    for (int k = 0; k < 3; ++k)
      w.pos[v][k] = precise ? mesh.precise_points[3 * v + k] : double(mesh.points[3 * v + k]);
  });
  w.tri.resize(nt);
  tbb::parallel_for(size_t(0), nt, [&](size_t t) {
    for (int k = 0; k < 3; ++k) w.tri[t][size_t(k)] = mesh.triangles[3 * t + k];
  });
  w.face_alive.assign(nt, 1);
  w.face_stamp.assign(nt, 0);
  w.face_pass.assign(nt, 0);
  w.live_faces = (long long)nt;
  fill_face_lists(w, stars);
  w.vertex_alive.assign(nv, 1);
  // NOTE: the manifold check's walk around each vertex tells this already;
  // finding it again here would repeat that walk over every vertex's star.
  if (on_boundary.size() == nv) {
    w.boundary.assign(on_boundary.begin(), on_boundary.end());
  } else {
    w.boundary.assign(nv, 0);
    tbb::parallel_for(size_t(0), nv, [&](size_t v) { w.boundary[v] = is_on_boundary(w, int(v)) ? 1 : 0; });
  }
  w.absolute.resize(nv);
  for (size_t v = 0; v < nv; ++v) w.absolute[v] = c.absolute[v];
  w.k1 = c.k1;
  w.k2 = c.k2;
  w.d1 = c.d1;
  w.d2 = c.d2;
  w.flags = c.flags;
  w.normal = mesh.normals;
  compute_weights(w);
  return w;
}

// NOTE: the vertices' and triangles' new indices are a serial prefix count;
// the copies into their new places run in parallel.
Mesh write_back(const WorkMesh& w, bool precise, const CurvatureStats& curvature_stats, const ContourStats& contour) {
  const size_t nv = w.pos.size(), nt = w.tri.size();
  std::vector<int32_t> remap(nv, -1);
  int32_t next = 0;
  for (size_t v = 0; v < nv; ++v)
    if (w.vertex_alive[v] && !w.vfaces[v].empty()) remap[v] = next++;
  std::vector<int32_t> slot(nt, -1);
  int32_t faces = 0;
  for (size_t t = 0; t < nt; ++t)
    if (w.face_alive[t]) slot[t] = faces++;
  Mesh out;
  out.points.resize(3 * size_t(next));
  if (precise) out.precise_points.resize(3 * size_t(next));
  out.normals.resize(3 * size_t(next));
  VertexCurvature& c = out.curvature;
  for (auto* a : {&c.k1, &c.k2, &c.mean, &c.gauss, &c.absolute}) a->resize(size_t(next));
  c.d1.resize(3 * size_t(next));
  c.d2.resize(3 * size_t(next));
  c.flags.resize(size_t(next));
  tbb::parallel_for(size_t(0), nv, [&](size_t v) {
    const int32_t r = remap[v];
    if (r < 0) return;
    for (int k = 0; k < 3; ++k) {
      out.points[3 * size_t(r) + k] = float(w.pos[v][k]);
      if (precise) out.precise_points[3 * size_t(r) + k] = w.pos[v][k];
      out.normals[3 * size_t(r) + k] = w.normal[3 * v + k];
      c.d1[3 * size_t(r) + k] = w.d1[3 * v + k];
      c.d2[3 * size_t(r) + k] = w.d2[3 * v + k];
    }
    c.k1[size_t(r)] = w.k1[v];
    c.k2[size_t(r)] = w.k2[v];
    c.mean[size_t(r)] = 0.5f * (w.k1[v] + w.k2[v]);
    c.gauss[size_t(r)] = w.k1[v] * w.k2[v];
    c.absolute[size_t(r)] = float(w.absolute[v]);
    c.flags[size_t(r)] = w.flags[v];
  });
  out.triangles.resize(3 * size_t(faces));
  tbb::parallel_for(size_t(0), nt, [&](size_t t) {
    if (slot[t] < 0) return;
    for (int k = 0; k < 3; ++k) out.triangles[3 * size_t(slot[t]) + size_t(k)] = remap[size_t(w.tri[t][size_t(k)])];
  });
  c.stats = curvature_stats;
  c.stats.vertices = next;
  out.contour = contour;
  compute_topology(out);
  return out;
}

}  // namespace isoform::reduce
