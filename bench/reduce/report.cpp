// The table of one input (Markdown, also what is printed) and its JSON:
// per target and method the triangles kept, times, the two-sided error
// absolute and over the bounding-box diagonal, ratios against the peers in
// the same run, and the topology of the result.
#include <cstdio>

#include "reduce_bench.h"

namespace isoform_reduce_bench {
namespace {

std::string fmt(const char* f, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

const Row* find(const std::vector<Row>& rows, double percent, const std::string& method) {
  for (const Row& r : rows)
    if (r.run.percent == percent && r.run.method == method && r.run.failure.empty()) return &r;
  return nullptr;
}

// a / b, or blank when the peer did not run (b = 0).
std::string ratio(double a, double b) { return b > 0 ? fmt("%.2f", a / b) : ""; }

}  // namespace

std::string markdown_table(const Input& in, const std::vector<Row>& rows) {
  std::string t;
  const bool graph = in.height != nullptr;
  t += "| removed | method | triangles | time s | CPU s | time / meshopt | CPU / meshopt | max | RMS | max / diag | RMS / diag |"
       " max / OpenMesh | RMS / OpenMesh |";
  if (graph) t += " vertical max | vertical RMS | knot max | knot RMS | knots uncovered | folded triangles |";
  t += " boundary edges | non-manifold edges | Euler | parts |\n";
  t += "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|";
  if (graph) t += "---:|---:|---:|---:|---:|---:|";
  t += "---:|---:|---:|---:|\n";
  for (const Row& r : rows) {
    t += "| " + fmt("%g%%", r.run.percent) + " | " + r.run.method + " | ";
    if (!r.run.failure.empty()) {
      t += "n/a: " + r.run.failure + " |\n";
      continue;
    }
    const Row* mo = find(rows, r.run.percent, "meshoptimizer");
    const Row* om = find(rows, r.run.percent, "OpenMesh quadric");
    const double max = r.m.error.max(), rms = r.m.error.rms();
    t += std::to_string(r.run.result.triangle_count()) + " | " + fmt("%.3f", r.run.time.wall) + " | " +
         fmt("%.3f", r.run.time.cpu) + " | " + ratio(r.run.time.wall, mo ? mo->run.time.wall : 0) +
         " | " + ratio(r.run.time.cpu, mo ? mo->run.time.cpu : 0) + " | " + fmt("%.3g", max) + " | " + fmt("%.3g", rms) + " | " + fmt("%.3g", max / in.diagonal) + " | " +
         fmt("%.3g", rms / in.diagonal) + " | " + ratio(max, om ? om->m.error.max() : 0) + " | " +
         ratio(rms, om ? om->m.error.rms() : 0) + " |";
    if (graph)
      t += " " + fmt("%.3g", r.m.vertical_max) + " | " + fmt("%.3g", r.m.vertical_rms) + " | " +
           fmt("%.3g", r.m.knot_max) + " | " + fmt("%.3g", r.m.knot_rms) + " | " + std::to_string(r.m.knots_uncovered) +
           " | " + std::to_string(r.m.folded) + " |";
    t += " " + std::to_string(r.m.stats.boundary_edges) + " | " + std::to_string(r.m.stats.nonmanifold_edges) +
         " | " + std::to_string(r.m.stats.euler_characteristic) + " | " + std::to_string(r.m.stats.parts) + " |\n";
  }
  return t;
}

Json input_json(const Input& in, const std::vector<Row>& rows) {
  Json runs = Json::array();
  for (const Row& r : rows) {
    Json j{{"method", r.run.method}, {"percent_removed", r.run.percent}, {"target_triangles", r.run.target}};
    if (!r.run.failure.empty()) {
      j["failure"] = r.run.failure;
      runs.push_back(j);
      continue;
    }
    const auto side = [](const SidedError& e) {
      return Json{{"max", e.max}, {"rms", e.rms}, {"mean", e.mean}, {"samples", e.samples}};
    };
    j["triangles"] = r.run.result.triangle_count();
    j["vertices"] = r.run.result.vertex_count();
    j["wall_seconds"] = r.run.time.wall;
    j["cpu_seconds"] = r.run.time.cpu;
    j["original_to_result"] = side(r.m.error.a_to_b);
    j["result_to_original"] = side(r.m.error.b_to_a);
    j["max"] = r.m.error.max();
    j["rms"] = r.m.error.rms();
    if (in.height) {
      j["vertical"] = Json{{"max", r.m.vertical_max}, {"rms", r.m.vertical_rms}};
      j["knots"] = Json{{"max", r.m.knot_max}, {"rms", r.m.knot_rms}, {"uncovered", r.m.knots_uncovered},
                         {"folded_triangles", r.m.folded}};
    }
    j["stats"] = Json{{"boundary_edges", r.m.stats.boundary_edges}, {"nonmanifold_edges", r.m.stats.nonmanifold_edges},
                      {"inconsistent_edges", r.m.stats.inconsistent_edges},
                      {"degenerate_triangles", r.m.stats.degenerate_triangles},
                      {"euler_characteristic", r.m.stats.euler_characteristic}, {"parts", r.m.stats.parts}};
    j["extra"] = r.run.extra;
    runs.push_back(j);
  }
  return Json{{"name", in.name}, {"what", in.what}, {"triangles", in.mesh.triangle_count()},
              {"vertices", in.mesh.vertex_count()}, {"bbox_diagonal", in.diagonal}, {"area", in.samples.area},
              {"facts", in.facts}, {"runs", runs}};
}

}  // namespace isoform_reduce_bench
