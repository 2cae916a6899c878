// OpenMesh's Decimater, the quality baseline: Garland-Heckbert quadrics
// (ModQuadric, no error bound, so the triangle target decides) with
// ModNormalFlipping (its default 90 degree limit), half-edge collapses to an
// existing vertex, double-precision points. Building the TriMesh is not
// timed; the face normals, the decimater's initialisation, the collapses
// and the garbage collection are.
#include <cmath>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include "reduce_bench.h"

namespace isoform_reduce_bench {
namespace {

using OMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMesh::DefaultTraitsDouble>;

void build(const Surface& s, OMesh& mesh) {
  std::vector<OMesh::VertexHandle> v(s.vertex_count());
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = mesh.add_vertex(OMesh::Point(s.points[3 * i], s.points[3 * i + 1], s.points[3 * i + 2]));
  for (size_t t = 0; t < s.triangle_count(); ++t)
    mesh.add_face(v[size_t(s.triangles[3 * t])], v[size_t(s.triangles[3 * t + 1])], v[size_t(s.triangles[3 * t + 2])]);
}

Surface extract(const OMesh& mesh) {
  Surface s;
  s.points.reserve(3 * mesh.n_vertices());
  for (const auto vh : mesh.vertices()) {
    const OMesh::Point& p = mesh.point(vh);
    s.points.insert(s.points.end(), {p[0], p[1], p[2]});
  }
  s.triangles.reserve(3 * mesh.n_faces());
  for (const auto fh : mesh.faces())
    for (const auto vh : mesh.fv_range(fh)) s.triangles.push_back(int32_t(vh.idx()));
  return s;
}

}  // namespace

Run run_openmesh(const Input& in, double percent, const Options& o) {
  Run r;
  r.method = "OpenMesh quadric";
  r.percent = percent;
  const size_t m = in.mesh.triangle_count();
  r.target = size_t(std::llround(double(m) * (1 - percent / 100)));
  r.time.wall = r.time.cpu = INFINITY;
  size_t locked = 0;
  for (int rep = 0; rep < o.reps; ++rep) {
    OMesh mesh;
    build(in.mesh, mesh);
    mesh.request_vertex_status();
    mesh.request_edge_status();
    mesh.request_face_status();
    locked = 0;
    if (o.lock_boundary)
      for (const auto vh : mesh.vertices())
        if (mesh.is_boundary(vh)) mesh.status(vh).set_locked(true), ++locked;
    const Timing t = timed([&] {
      mesh.request_face_normals();
      mesh.update_face_normals();
      OpenMesh::Decimater::DecimaterT<OMesh> decimater(mesh);
      OpenMesh::Decimater::ModQuadricT<OMesh>::Handle quadric;
      OpenMesh::Decimater::ModNormalFlippingT<OMesh>::Handle flipping;
      decimater.add(quadric);
      decimater.add(flipping);
      decimater.module(quadric).unset_max_err();
      decimater.initialize();
      decimater.decimate_to_faces(0, r.target);
      mesh.garbage_collection();
    });
    r.time.wall = std::min(r.time.wall, t.wall);
    r.time.cpu = std::min(r.time.cpu, t.cpu);
    if (rep + 1 == o.reps) r.result = compact(extract(mesh));
  }
  r.extra = Json{{"locked_vertices", locked}, {"max_normal_deviation_degrees", 90}};
  return r;
}

}  // namespace isoform_reduce_bench
