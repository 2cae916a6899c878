// CGAL's Monge_via_jet_fitting: a degree-d jet fitted in a PCA frame to the
// vertex and its k-ring (isoform's own ring gathering, so the neighbourhood
// is exactly isoform's default platelet), then the Monge form's principal
// curvatures, its normal turned toward the mesh's normal. CGAL's Monge
// coefficients are the curvatures of z = (k_max x^2 + k_min y^2) / 2 along
// that normal, the opposite of isoform's sign: isoform's k1 is -k_min.
// Parallel over vertices with TBB, one fitter per thread.
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <memory>
#include <stdexcept>

#include "curvature_bench.h"
#include "libcore/curvature/vertex_rings.h"

namespace isoform_curvature_bench {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Fitter = CGAL::Monge_via_jet_fitting<Kernel>;

struct Scratch {
  Fitter fitter;
  isoform::RingScratch rings;
  std::vector<Point> points;
};

// The jet needs (d + 1)(d + 2) / 2 points; rings are added until it has them.
void fit_vertex(const Case& c, const isoform::VertexRings& rings, size_t v, int degree, int ring_count,
                const std::vector<float>& normals, Scratch& s, Curvatures& out) {
  const size_t wanted = size_t((degree + 1) * (degree + 2) / 2);
  int k = ring_count;
  isoform::gather_rings(rings, int32_t(v), k, s.rings);
  while (s.rings.out.size() + 1 < wanted && k < ring_count + 4) isoform::gather_rings(rings, int32_t(v), ++k, s.rings);
  if (s.rings.out.size() + 1 < wanted) return;  // left at zero; counted by the caller
  s.points.clear();
  auto at = [&](size_t w) { return Point(c.points[3 * w], c.points[3 * w + 1], c.points[3 * w + 2]); };
  s.points.push_back(at(v));
  for (int32_t w : s.rings.out) s.points.push_back(at(size_t(w)));
  Fitter::Monge_form form = s.fitter(s.points.begin(), s.points.end(), size_t(degree), 2);
  form.comply_wrt_given_normal(Vector(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]));
  const double k_max = form.principal_curvatures(0), k_min = form.principal_curvatures(1);
  out.k1[v] = float(-k_min);
  out.k2[v] = float(-k_max);
  out.mean[v] = float(-0.5 * (k_max + k_min));
  out.gauss[v] = float(k_max * k_min);
}

isoform::VertexRings ring_table(const Case& c) {
  isoform::Mesh topology;
  topology.points.resize(c.points.size());
  topology.triangles = c.triangles;
  return isoform::VertexRings(topology);
}

// Every stride-th vertex (1: all of them).
Curvatures fit_all(const Case& c, const isoform::VertexRings& rings, int degree, int ring_count,
                   const std::vector<float>& normals, int threads, size_t stride) {
  const size_t n = c.vertex_count();
  Curvatures out;
  for (auto* a : {&out.k1, &out.k2, &out.mean, &out.gauss}) a->assign(n, 0.0f);
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n / stride, 4096), [&](const tbb::blocked_range<size_t>& r) {
      Scratch& s = scratch.local();
      for (size_t i = r.begin(); i != r.end(); ++i) fit_vertex(c, rings, i * stride, degree, ring_count, normals, s, out);
    });
  });
  return out;
}

}  // namespace

void run_cgal(const Case& c, const Options& o, int degree, const std::vector<float>& normals,
              std::vector<Result>& out) {
  Result r;
  r.method = "CGAL jet d" + std::to_string(degree) + ", " + std::to_string(o.cgal_rings) + "-ring";
  Curvatures one, two;
  // The ring table is part of the method's work, as isoform builds its own
  // (serially, once per call), so its time is added to both columns.
  isoform::VertexRings* rings = nullptr;
  const Timing table = best_of(1, [&] { rings = new isoform::VertexRings(ring_table(c)); });
  std::unique_ptr<isoform::VertexRings> owned(rings);
  // CGAL's fit is far slower than the others', too slow to time on every
  // vertex of a large mesh: the one-thread time is taken on every
  // cgal_stride-th vertex and scaled to the whole mesh.
  const size_t stride = size_t(o.cgal_stride);
  r.one = best_of(o.peer_reps, [&] { one = fit_all(c, *rings, degree, o.cgal_rings, normals, 1, stride); });
  r.one.wall = r.one.wall * double(stride) + table.wall;
  r.one.cpu = r.one.cpu * double(stride) + table.cpu;
  r.two = best_of(o.peer_reps, [&] { two = fit_all(c, *rings, degree, o.cgal_rings, normals, 2, 1); });
  r.two.wall += table.wall;
  r.two.cpu += table.cpu;
  r.same_bits = true;
  for (size_t v = 0; v < c.vertex_count(); v += stride) r.same_bits = r.same_bits && one.k1[v] == two.k1[v];
  r.rms = rms_of(c, two);
  r.extra = Json{{"degree", degree}, {"rings", o.cgal_rings}, {"one_thread_time_from_every_nth_vertex", stride}};
  out.push_back(r);
}

}  // namespace isoform_curvature_bench
