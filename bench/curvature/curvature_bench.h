// isoform_curvature_bench: isoform's surface curvature (seed's and default
// methods, through the C API) against VTK's vtkCurvatures and CGAL's
// Monge_via_jet_fitting, on the same ~1M-vertex meshes with exact curvature,
// in one run. Each method gets the same double-precision points and
// triangles; times exclude building each library's own input structures.
#pragma once

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "isoform.h"
#include "tests/curvature/truth.h"

namespace isoform_curvature_bench {

using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

// One test mesh: a truth shape, regular or jittered, with exact values.
struct Case {
  std::string name;  // e.g. "torus-jittered"
  isoform::truth::Shape shape;
  double jitter = 0;
  std::vector<double> points;     // 3 per vertex
  std::vector<int32_t> triangles; // 3 per triangle
  std::vector<float> exact_normals;
  std::vector<isoform::truth::Exact> exact;
  size_t vertex_count() const { return points.size() / 3; }
};

// Per-vertex results of one method, in isoform's sign (positive where the
// surface bends away from its outward normal) and k1 >= k2.
struct Curvatures {
  std::vector<float> k1, k2, mean, gauss;
};

double seconds_since(Clock::time_point start);
// CPU time of the whole process (all its threads) in seconds.
double process_cpu_seconds();

// Wall and CPU seconds of a call. On a shared machine the wall time also
// counts the time other processes had the cores; the CPU time does not.
struct Timing {
  double wall = 0, cpu = 0;
};

// Calls body() reps times; the smallest wall and the smallest CPU time.
template <class Body>
Timing best_of(int reps, Body&& body) {
  Timing best{1e300, 1e300};
  for (int r = 0; r < reps; ++r) {
    const Clock::time_point t = Clock::now();
    const double c = process_cpu_seconds();
    body();
    best.cpu = std::min(best.cpu, process_cpu_seconds() - c);
    best.wall = std::min(best.wall, seconds_since(t));
  }
  return best;
}

// The smaller wall and the smaller CPU time of two timings.
inline Timing better(const Timing& a, const Timing& b) {
  return {std::min(a.wall, b.wall), std::min(a.cpu, b.cpu)};
}

// One method's figures on one case.
struct Result {
  std::string method;
  Timing one;               // best times with one thread
  Timing two;               // with two threads; zero when the method is serial only
  double setup_seconds = 0;  // untimed-by-the-table preparation that the method needs (reported)
  std::string setup_what;
  isoform::truth::Rms rms;   // against exact, over all vertices
  bool same_bits = true;     // one thread and two gave identical results
  Json extra = Json::object();
};

struct Options {
  int resolution_torus = 1290;    // 1290 x 774 = 998,460 vertices
  int resolution_ellipsoid = 1632;// cube sphere of 6 x 408^2 quads: 998,788 vertices
  double jitter = 0.25;
  int reps = 3;        // timed calls per isoform method and thread count; the best counts
  int rounds = 3;      // isoform's methods called in turn this many times; the best counts
  int peer_reps = 1;   // the same for VTK and CGAL (far slower)
  int cgal_rings = 3;  // CGAL's neighbourhood: the k-ring of isoform's default platelet
  int cgal_stride = 10;  // CGAL's one-thread time from every n-th vertex, scaled
  bool cgal4 = true;   // also CGAL's degree-4 jet
  bool vtk = true;
  bool cgal = true;
  std::vector<std::string> shapes{"torus", "ellipsoid"};
  std::string json_path;
};


// Throws std::runtime_error with isoform's message unless status is ISOFORM_OK.
void check(isoform_status status, const char* what);

Case make_case(isoform::truth::Shape shape, int resolution, double jitter);
isoform::truth::Rms rms_of(const Case& c, const Curvatures& r);

// isoform's methods on c through the C API; each adds its Result rows.
void run_isoform(const Case& c, const Options& o, std::vector<Result>& out, std::vector<float>& mesh_normals);
// VTK's vtkCurvatures (mean and Gaussian), serial.
void run_vtk(const Case& c, const Options& o, std::vector<Result>& out);
// CGAL's jet fitting of degree d over the k-ring, oriented by mesh_normals.
void run_cgal(const Case& c, const Options& o, int degree, const std::vector<float>& mesh_normals,
              std::vector<Result>& out);

// The table on stdout and the JSON report.
Json case_json(const Case& c, const std::vector<Result>& results);
void print_case(const Case& c, const std::vector<Result>& results);

}  // namespace isoform_curvature_bench
