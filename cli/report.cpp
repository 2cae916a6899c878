// Text and JSON summaries of grids and meshes.
#include "report.h"

#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace isoform::cli {
namespace {

// Wide enough for the longest label, "non-manifold edges".
constexpr int kLabelWidth = 20;

template <class T>
Json triple(const T (&v)[3]) {
  return Json::array({v[0], v[1], v[2]});
}

template <class T>
std::string format_triple(const T (&v)[3], const char* separator) {
  std::ostringstream text;
  text << format_number(double(v[0])) << separator << format_number(double(v[1])) << separator
       << format_number(double(v[2]));
  return text.str();
}

std::string format_range(double low, double high) {
  return "[" + format_number(low) + ", " + format_number(high) + "]";
}

void print_transform(std::ostream& out, const double (&m)[16]) {
  for (int row = 0; row < 4; ++row) {
    std::ostringstream text;
    for (int col = 0; col < 4; ++col) text << std::setw(12) << format_number(m[4 * row + col]);
    print_row(out, row == 0 ? "  transform" : "", text.str());
  }
}

}  // namespace

std::string class_name(int grid_class) {
  switch (grid_class) {
    case ISOFORM_CLASS_LEVEL_SET: return "level set";
    case ISOFORM_CLASS_FOG: return "fog volume";
    default: return "other";
  }
}

std::string format_number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string format_seconds(double seconds) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(2) << seconds << " s";
  return text.str();
}

void print_row(std::ostream& out, const std::string& label, const std::string& value) {
  out << std::left << std::setw(kLabelWidth) << label << std::right << value << '\n';
}

Json grid_json(const isoform_grid_info& info) {
  Json transform = Json::array();
  for (int row = 0; row < 4; ++row)
    transform.push_back({info.transform[4 * row], info.transform[4 * row + 1],
                         info.transform[4 * row + 2], info.transform[4 * row + 3]});
  const bool scalar = info.is_scalar != 0;
  return {{"name", std::string(info.name)},
          {"value_type", std::string(info.value_type)},
          {"class", class_name(info.grid_class)},
          {"scalar", scalar},
          {"value_min", scalar ? Json(info.value_min) : Json()},
          {"value_max", scalar ? Json(info.value_max) : Json()},
          {"background", info.background},
          {"active_voxels", info.active_voxels},
          {"bbox_min", triple(info.bbox_min)},
          {"bbox_max", triple(info.bbox_max)},
          {"voxel_size", triple(info.voxel_size)},
          {"transform", transform},
          {"space", info.space[0] ? Json(std::string(info.space)) : Json()},
          {"unit", info.unit[0] ? Json(std::string(info.unit)) : Json()}};
}

std::string frame_text(const isoform_grid_info& info) {
  const std::string space = info.space[0] ? std::string(info.space) : "not stated";
  const std::string unit = info.unit[0] ? std::string(info.unit) : "not stated";
  return space + ", unit " + unit;
}

void print_grid(std::ostream& out, int index, const isoform_grid_info& info) {
  out << "grid " << index << ": " << info.name << '\n';
  const bool scalar = info.is_scalar != 0;
  print_row(out, "  value type", std::string(info.value_type) + (scalar ? " (scalar)" : " (not scalar)"));
  print_row(out, "  class", class_name(info.grid_class));
  print_row(out, "  value range", scalar ? format_range(info.value_min, info.value_max) : "-");
  print_row(out, "  background", format_number(info.background));
  print_row(out, "  active voxels", std::to_string(info.active_voxels));
  print_row(out, "  index bbox",
            "[" + format_triple(info.bbox_min, ", ") + "] .. [" + format_triple(info.bbox_max, ", ") + "]");
  print_row(out, "  voxel size", format_triple(info.voxel_size, " x "));
  print_row(out, "  world frame", frame_text(info));
  print_transform(out, info.transform);
}

Json mesh_json(const isoform_mesh_stats& stats) {
  return {{"vertices", stats.vertices},
          {"triangles", stats.triangles},
          {"parts", stats.parts},
          {"boundary_edges", stats.boundary_edges},
          {"nonmanifold_edges", stats.nonmanifold_edges},
          {"inconsistent_edges", stats.inconsistent_edges},
          {"degenerate_triangles", stats.degenerate_triangles},
          {"euler_characteristic", stats.euler_characteristic},
          {"isovalue", stats.isovalue},
          {"isovalue_was_auto", stats.isovalue_was_auto != 0},
          {"ambiguous_faces", stats.ambiguous_faces},
          {"degenerate_saddles", stats.degenerate_saddles},
          {"extra_points", stats.extra_points},
          {"centroid_points", stats.centroid_points},
          {"bbox_min", triple(stats.bbox_min)},
          {"bbox_max", triple(stats.bbox_max)}};
}

void print_mesh(std::ostream& out, const isoform_mesh_stats& stats) {
  print_row(out, "vertices", std::to_string(stats.vertices));
  print_row(out, "triangles", std::to_string(stats.triangles));
  print_row(out, "parts", std::to_string(stats.parts));
  print_row(out, "boundary edges", std::to_string(stats.boundary_edges));
  print_row(out, "non-manifold edges", std::to_string(stats.nonmanifold_edges));
  print_row(out, "isovalue",
            format_number(stats.isovalue) + (stats.isovalue_was_auto ? " (automatic)" : ""));
  print_row(out, "ambiguous faces", std::to_string(stats.ambiguous_faces));
  print_row(out, "extra points", std::to_string(stats.extra_points));
}

void print_json(const Json& j) { std::cout << j.dump(2) << '\n'; }

}  // namespace isoform::cli
