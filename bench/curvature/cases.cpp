// The benchmark's meshes, from the test suite's exact shapes, and their
// errors against exact curvature.
#include <ctime>
#include <stdexcept>

#include "curvature_bench.h"

namespace isoform_curvature_bench {

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void check(isoform_status status, const char* what) {
  if (status != ISOFORM_OK) throw std::runtime_error(std::string(what) + ": " + isoform_last_error());
}

Case make_case(isoform::truth::Shape shape, int resolution, double jitter) {
  Case c;
  c.shape = shape;
  c.jitter = jitter;
  c.name = std::string(isoform::truth::shape_name(shape)) + (jitter > 0 ? "-jittered" : "-regular");
  // A fixed seed: every run measures the same meshes.
  isoform::Mesh m = isoform::truth::shape_mesh(shape, resolution, jitter, 7, c.exact);
  c.points = std::move(m.precise_points);
  c.triangles = std::move(m.triangles);
  c.exact_normals = isoform::truth::shape_normals(shape, m);
  return c;
}

isoform::truth::Rms rms_of(const Case& c, const Curvatures& r) {
  // truth::rms_error reads a mesh's curvature arrays; lend it ours.
  isoform::Mesh m;
  m.curvature.k1 = r.k1;
  m.curvature.k2 = r.k2;
  m.curvature.mean = r.mean;
  m.curvature.gauss = r.gauss;
  if (r.k1.size() != c.vertex_count()) throw std::runtime_error("rms_of: result size differs from the mesh");
  return isoform::truth::rms_error(m, c.exact);
}

}  // namespace isoform_curvature_bench
