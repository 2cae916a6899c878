#include "report_files.h"

#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "libcore/errors.h"
#include "libcore/meshio/atomic_file.h"

namespace isoform::compare {
namespace {

using Json = nlohmann::ordered_json;

// JSON has no NaN: unknown values are null.
Json number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

Json stats_json(const Stats& s) {
  return {{"count", s.count}, {"max", number(s.max)}, {"rms", number(s.rms)}, {"mean", number(s.mean)}};
}

Json spread_json(const Spread& s) {
  return {{"count", s.count}, {"p05", number(s.p05)}, {"p50", number(s.p50)}, {"p95", number(s.p95)},
          {"mean", number(s.mean)}, {"stddev", number(s.stddev)}};
}

Json surface_json(const SurfaceMetrics& m) {
  return {{"name", m.name},
          {"samples", m.samples},
          {"failed_samples", m.failed_samples},
          {"deviation", stats_json(m.deviation)},
          {"data_point_error", stats_json(m.data_point_error)},
          {"normal_gap_radians", stats_json(m.normal_gap)},
          {"position_gap", stats_json(m.position_gap)},
          {"tangent_plane_gap_radians", stats_json(m.tangent_plane_gap)},
          {"folded_edges", m.folded_edges},
          {"mean_curvature_jump", stats_json(m.mean_curvature_jump)},
          {"mean_curvature_error", stats_json(m.mean_curvature_error)},
          {"mean_curvature", spread_json(m.mean_curvature)},
          {"gauss_curvature", spread_json(m.gauss_curvature)},
          {"evaluation_seconds", m.evaluation_seconds},
          {"seconds_per_million_samples", m.seconds_per_million},
          {"tessellation_triangles", m.tessellation_triangles}};
}

std::string g(double x, int digits = 4) {
  if (!std::isfinite(x)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

// One table row: a label, then one value per surface.
template <class F>
void row(std::ostringstream& out, const std::string& label, const CompareResult& r, F value) {
  out << "| " << label << " |";
  for (const SurfaceMetrics& m : r.surfaces) out << " " << value(m) << " |";
  out << "\n";
}

void write_file(const std::string& path, const std::string& text, std::unique_ptr<meshio::AtomicFile>& file) {
  file = std::make_unique<meshio::AtomicFile>(path);
  file->write(text);
}

}  // namespace

std::string report_json(const CompareResult& r, const StudyInfo& info) {
  Json j;
  j["input"] = info.input;
  j["base_vertices"] = r.base_vertices;
  j["base_triangles"] = r.base_triangles;
  j["level"] = r.level;
  j["samples_per_triangle"] = (r.level + 1) * (r.level + 2) / 2;
  j["edge_samples_per_edge"] = r.level;
  j["reference"] = {{"kind", r.reference_kind}, {"description", r.reference_description},
                    {"deviation_unit", r.deviation_unit}};
  j["loop"] = info.loop_options;
  j["sample_table_rows"] = r.rows.size();
  Json surfaces = Json::array();
  for (const SurfaceMetrics& m : r.surfaces) surfaces.push_back(surface_json(m));
  j["surfaces"] = surfaces;
  j["notes"] = r.notes;
  return j.dump(2) + "\n";
}

std::string samples_csv(const CompareResult& r) {
  std::ostringstream out;
  out.precision(17);
  out << "triangle,u,v";
  for (const SurfaceMetrics& m : r.surfaces)
    for (const char* q : {"x", "y", "z", "deviation", "mean", "gauss"}) out << "," << m.name << "_" << q;
  out << "\n";
  for (size_t i = 0; i < r.rows.size(); ++i) {
    out << r.rows[i].triangle << "," << r.rows[i].u << "," << r.rows[i].v;
    for (size_t s = 0; s < r.surfaces.size(); ++s) {
      const SampleValues& v = r.values[s][i];
      for (double x : {v.x, v.y, v.z, v.deviation, v.mean, v.gauss}) {
        out << ",";
        if (std::isfinite(x)) out << x; else out << "nan";
      }
    }
    out << "\n";
  }
  return out.str();
}

std::string report_markdown(const CompareResult& r, const StudyInfo& info) {
  std::ostringstream out;
  out << "# Comparison of smooth surfaces over " << (info.input.empty() ? "a mesh" : info.input) << "\n\n";
  out << r.base_vertices << " vertices, " << r.base_triangles << " triangles; level " << r.level << ": "
      << (r.level + 1) * (r.level + 2) / 2 << " samples per triangle, " << r.level << " per edge. Loop: "
      << info.loop_options << ".\n";
  out << "Reference: " << (r.reference_kind == "none" ? "none" : r.reference_description + " (deviation in " + r.deviation_unit + ")")
      << ".\n\n";
  out << "| measure |";
  for (const SurfaceMetrics& m : r.surfaces) out << " " << m.name << " |";
  out << "\n|---|";
  for (size_t i = 0; i < r.surfaces.size(); ++i) out << "---:|";
  out << "\n";
  row(out, "deviation max", r, [](const SurfaceMetrics& m) { return m.deviation.count ? g(m.deviation.max) : "-"; });
  row(out, "deviation RMS", r, [](const SurfaceMetrics& m) { return m.deviation.count ? g(m.deviation.rms) : "-"; });
  row(out, "error at data points, max", r, [](const SurfaceMetrics& m) { return g(m.data_point_error.max); });
  row(out, "error at data points, RMS", r, [](const SurfaceMetrics& m) { return g(m.data_point_error.rms); });
  row(out, "normal gap across edges, max (rad)", r, [](const SurfaceMetrics& m) { return g(m.normal_gap.max); });
  row(out, "normal gap across edges, RMS (rad)", r, [](const SurfaceMetrics& m) { return g(m.normal_gap.rms); });
  row(out, "tangent-plane gap across edges, max (rad)", r,
      [](const SurfaceMetrics& m) { return g(m.tangent_plane_gap.max); });
  row(out, "folded edges (normals apart by more than pi/2)", r,
      [](const SurfaceMetrics& m) { return std::to_string(m.folded_edges); });
  row(out, "mean-curvature jump across edges, max", r, [](const SurfaceMetrics& m) { return g(m.mean_curvature_jump.max); });
  row(out, "mean-curvature jump across edges, RMS", r, [](const SurfaceMetrics& m) { return g(m.mean_curvature_jump.rms); });
  row(out, "H error against the reference, RMS", r,
      [](const SurfaceMetrics& m) { return m.mean_curvature_error.count ? g(m.mean_curvature_error.rms) : "-"; });
  row(out, "H median", r, [](const SurfaceMetrics& m) { return g(m.mean_curvature.p50); });
  row(out, "H spread (5th-95th percentile)", r,
      [](const SurfaceMetrics& m) { return g(m.mean_curvature.p05) + " .. " + g(m.mean_curvature.p95); });
  row(out, "H standard deviation", r, [](const SurfaceMetrics& m) { return g(m.mean_curvature.stddev); });
  row(out, "seconds per million samples", r, [](const SurfaceMetrics& m) { return g(m.seconds_per_million, 3); });
  row(out, "tessellation triangles", r, [](const SurfaceMetrics& m) { return std::to_string(m.tessellation_triangles); });
  row(out, "samples not evaluated", r, [](const SurfaceMetrics& m) { return std::to_string(m.failed_samples); });
  for (const std::string& n : r.notes) out << "\nNote: " << n << ".\n";
  out << "\nH is the mean curvature (positive where the surface bends away from its normal), in 1/world unit.\n";
  return out.str();
}

void write_report(const CompareResult& r, const StudyInfo& info, const std::string& directory) {
  struct stat st;
  if (::stat(directory.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    throw IoError(directory + ": no such folder for the comparison report");
  std::unique_ptr<meshio::AtomicFile> files[3];
  write_file(directory + "/report.json", report_json(r, info), files[0]);
  write_file(directory + "/samples.csv", samples_csv(r), files[1]);
  write_file(directory + "/report.md", report_markdown(r, info), files[2]);
  for (auto& f : files) f->commit();
}

}  // namespace isoform::compare
