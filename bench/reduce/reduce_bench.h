// isoform_reduce_bench: isoform's reduction (Chapter 5, through the C API)
// against OpenMesh's quadric decimater and meshoptimizer's simplifier, on the
// same meshes at the same triangle targets, in one run, with the error of
// each result measured the same way (metro.h) against the original.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "isoform.h"
#include "metro.h"

namespace isoform_reduce_bench {

using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

// A triangle mesh as the methods exchange it: double points, int32 triangles.
struct Surface {
  std::vector<double> points;      // 3 per vertex
  std::vector<int32_t> triangles;  // 3 per triangle
  size_t vertex_count() const { return points.size() / 3; }
  size_t triangle_count() const { return triangles.size() / 3; }
  MeshView view() const { return {points.data(), vertex_count(), triangles.data(), triangle_count()}; }
};

// The same surface without the vertices no triangle uses (meshoptimizer
// returns indices into the unchanged vertex array).
Surface compact(const Surface& s);

// One input and what every result on it is measured against.
struct Input {
  std::string name;   // "graph", "contour"
  std::string what;   // how it was made, for the report
  Surface mesh;
  double (*height)(double x, double y) = nullptr;  // the graph's function, else null
  double diagonal = 0;                             // of the bounding box
  SurfaceSamples samples;
  std::unique_ptr<TriangleTree> tree;
  isoform_mesh_stats stats{};  // of the original, from isoform_mesh_from_arrays_f64
  Json facts = Json::object();
};

struct Options {
  std::string graph = "trigonometric";  // one of Table 4.1's nine
  int graph_knots = 708;                // per side: 2 * 707^2 = 999,698 triangles
  double contour_spacing = 0.68;        // headsq resampled to this isotropic spacing: ~1M triangles
  double contour_iso = 1150.5;          // bone
  std::vector<double> percents{50, 80, 90, 99};
  std::vector<std::string> inputs{"graph", "contour"};
  std::vector<std::string> methods{"isoform", "openmesh", "meshopt"};
  size_t samples = 1000000;  // area samples per surface and side
  bool lock_boundary = true;  // every method keeps the graph's border (the contour has none)
  bool isoform_lock_boundary = false;  // isoform keeps it by lock_boundary, not by its graph option
  int reps = 1;
  std::string data_dir;
  std::string json_path, markdown_path;
  std::string save_inputs;  // folder to write each input as <name>.ply (profiling `isoform reduce`); empty = none
};

struct Timing {
  double wall = 0, cpu = 0;  // seconds; CPU of the whole process (all threads)
};
double process_cpu_seconds();

// Wall and CPU time of body().
template <class Body>
Timing timed(Body&& body) {
  const Clock::time_point t = Clock::now();
  const double c = process_cpu_seconds();
  body();
  return Timing{std::chrono::duration<double>(Clock::now() - t).count(), process_cpu_seconds() - c};
}

// One method's result at one target.
struct Run {
  std::string method;
  double percent = 0;      // of the original triangles to remove
  size_t target = 0;       // triangles to keep
  Timing time;             // the best of the reps
  Surface result;          // compacted
  std::string failure;     // empty when the method ran
  Json extra = Json::object();
};

// Throws std::runtime_error with isoform's message unless status is ISOFORM_OK.
void check(isoform_status status, const char* what);

Input make_graph(const Options& o);
Input make_contour(const Options& o);
// Samples, tree and diagonal of the input's mesh.
void prepare_reference(Input& in, const Options& o);
// Writes the input as a PLY file (isoform_mesh_save), for profiling `isoform reduce` on it.
void save_input(const Input& in, const std::string& path);

bool isoform_reduce_available();
Run run_isoform(const Input& in, double percent, const Options& o);
Run run_openmesh(const Input& in, double percent, const Options& o);
Run run_meshopt(const Input& in, double percent, const Options& o);

// The errors and topology of a run's result against its input.
struct Measured {
  TwoSidedError error;
  double vertical_max = -1, vertical_rms = -1;  // graphs only: at the result's samples
  // Graphs only: the result's height over each original knot against f
  // there (the seed's 5.41), and the knots no result triangle covers.
  double knot_max = -1, knot_rms = -1;
  size_t knots_uncovered = 0;
  size_t folded = 0;  // graphs only: triangles whose (x, y) projection is clockwise or flat
  isoform_mesh_stats stats{};                   // of the result, by isoform_mesh_from_arrays_f64
};
Measured measure(const Input& in, const Run& run, const Options& o);

// Tables on stdout and in Markdown; the JSON of one input.
struct Row {
  Run run;
  Measured m;
};
std::string markdown_table(const Input& in, const std::vector<Row>& rows);
Json input_json(const Input& in, const std::vector<Row>& rows);

}  // namespace isoform_reduce_bench
