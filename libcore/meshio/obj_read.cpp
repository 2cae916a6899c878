// Reading Wavefront OBJ: only v, vn and f describe the surface; texture
// coordinates, groups, materials and smoothing groups are passed over.
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "../errors.h"
#include "formats.h"
#include "polygon_split.h"
#include "text_cursor.h"

namespace isoform::meshio {
namespace {

struct Corner {
  int32_t vertex;
  int32_t normal;  // index into the vn table, or -1
};

class ObjParser {
 public:
  ObjParser(std::string_view text, const std::string& path) : cursor_(text), path_(path) {}
  Mesh run();

 private:
  void read_point();
  void read_normal();
  void read_triple(std::vector<float>& out, const char* what);
  void read_face();
  Corner read_corner(std::string_view token);
  int32_t resolve(std::string_view index, size_t defined, const char* what);
  void assign_normal(const Corner& corner);
  void keep_normals();
  [[noreturn]] void fail(const std::string& what) const;

  TextCursor cursor_;
  const std::string& path_;
  Mesh mesh_;
  std::vector<float> normal_table_;  // the vn lines
  std::vector<int32_t> normal_of_;   // per vertex: its vn, or -1 while it has none
  bool normals_consistent_ = true;
  std::vector<Corner> corners_;      // of the face being read
  std::vector<int32_t> face_vertices_;  // the vertices of corners_
};

Mesh ObjParser::run() {
  do {
    std::string_view keyword = cursor_.token_on_line();
    if (keyword == "v") {
      read_point();
    } else if (keyword == "vn") {
      read_normal();
    } else if (keyword == "f") {
      read_face();
    }
  } while (cursor_.next_line());
  keep_normals();
  return std::move(mesh_);
}

void ObjParser::read_point() {
  read_triple(mesh_.points, "v");
  normal_of_.push_back(-1);
}

void ObjParser::read_normal() { read_triple(normal_table_, "vn"); }

// The first three numbers; a "v" line may go on with w or a colour.
void ObjParser::read_triple(std::vector<float>& out, const char* what) {
  for (int k = 0; k < 3; ++k) {
    std::string_view token = cursor_.token_on_line();
    float value;
    if (token.empty()) fail(std::string(what) + " needs three numbers");
    if (!parse_number(token, value)) fail(not_a_float(token));
    if (!std::isfinite(value)) fail(std::string(what) + " has a value that is not finite");
    out.push_back(value);
  }
}

// A polygon is split into triangles by split_polygon (a convex one into the
// fan from its first corner).
void ObjParser::read_face() {
  corners_.clear();
  for (std::string_view token = cursor_.token_on_line(); !token.empty() && token[0] != '#';
       token = cursor_.token_on_line()) {
    corners_.push_back(read_corner(token));
  }
  if (corners_.size() < 3) {
    fail("a face has " + std::to_string(corners_.size()) + " corners; it needs at least 3");
  }
  for (const Corner& corner : corners_) assign_normal(corner);
  face_vertices_.clear();
  for (const Corner& corner : corners_) face_vertices_.push_back(corner.vertex);
  split_polygon(face_vertices_, [this](int32_t vertex) {
    const float* p = &mesh_.points[3 * size_t(vertex)];
    return std::array<double, 3>{p[0], p[1], p[2]};
  }, mesh_.triangles);
}

// Forms "v", "v/t", "v/t/n" and "v//n"; the texture index is not used.
Corner ObjParser::read_corner(std::string_view token) {
  size_t slash = token.find('/');
  Corner corner{resolve(token.substr(0, slash), mesh_.vertex_count(), "vertex"), -1};
  if (slash == std::string_view::npos) return corner;
  size_t second = token.find('/', slash + 1);
  if (second == std::string_view::npos || second + 1 == token.size()) return corner;
  corner.normal = resolve(token.substr(second + 1), normal_table_.size() / 3, "normal");
  return corner;
}

// OBJ counts from 1; a negative index counts back from the last one defined.
int32_t ObjParser::resolve(std::string_view index, size_t defined, const char* what) {
  long long number;
  if (!parse_number(index, number) || number == 0) {
    fail("\"" + std::string(index) + "\" is not a valid " + what + " index");
  }
  long long resolved = number > 0 ? number - 1 : static_cast<long long>(defined) + number;
  if (resolved < 0 || resolved >= static_cast<long long>(defined)) {
    fail("a face refers to " + std::string(what) + " " + std::string(index) + " but " +
         std::to_string(defined) + " are defined before it");
  }
  return static_cast<int32_t>(resolved);
}

// A vertex may meet the same normal under two vn indices (exporters repeat
// them), so a second index counts as a conflict only if its value differs.
void ObjParser::assign_normal(const Corner& corner) {
  if (corner.normal < 0) return;
  int32_t& current = normal_of_[size_t(corner.vertex)];
  if (current < 0) {
    current = corner.normal;
    return;
  }
  for (size_t k = 0; k < 3; ++k) {
    if (normal_table_[3 * size_t(current) + k] != normal_table_[3 * size_t(corner.normal) + k]) {
      normals_consistent_ = false;
    }
  }
}

// Per-vertex normals exist only when each vertex was given exactly one;
// anything else (creases, missing normals) is left for the caller to estimate.
void ObjParser::keep_normals() {
  if (!normals_consistent_ || normal_table_.empty()) return;
  for (int32_t normal : normal_of_) {
    if (normal < 0) return;
  }
  mesh_.normals.reserve(mesh_.points.size());
  for (int32_t normal : normal_of_) {
    const float* n = &normal_table_[3 * size_t(normal)];
    mesh_.normals.insert(mesh_.normals.end(), n, n + 3);
  }
}

void ObjParser::fail(const std::string& what) const {
  throw FormatError(path_ + ": line " + std::to_string(cursor_.line()) + ": " + what);
}

}  // namespace

Mesh read_obj(std::string_view bytes, const std::string& path) {
  return ObjParser(bytes, path).run();
}

}  // namespace isoform::meshio
