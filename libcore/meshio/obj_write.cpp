// Writing Wavefront OBJ. Numbers are written in their shortest form that
// reads back to the same float (std::to_chars), so a save and load of OBJ
// keeps the points bit for bit, and the "C" locale is used whatever the
// process's locale says. Points that need double precision
// (points_need_double) are written in the shortest form of the double.
#include <charconv>
#include <string>
#include <vector>

#include "formats.h"

namespace isoform::meshio {
namespace {

template <class Number>
void append_number(std::string& line, Number value) {
  char text[32];  // longer than any float or 64-bit integer
  line.append(text, std::to_chars(text, text + sizeof text, value).ptr);
}

// One "keyword x y z" line per triple; the line's storage is reused.
template <class Number>
void write_triples(AtomicFile& file, const char* keyword, const std::vector<Number>& values) {
  std::string line;
  for (size_t i = 0; i + 2 < values.size(); i += 3) {
    line = keyword;
    for (size_t k = 0; k < 3; ++k) {
      line += ' ';
      append_number(line, values[i + k]);
    }
    line += '\n';
    file.write(line);
  }
}

// "f a b c", or "f a//a b//b c//c" when each vertex has its normal of the
// same number.
void write_faces(const Mesh& mesh, AtomicFile& file) {
  bool normals = !mesh.normals.empty();
  std::string line;
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    line = "f";
    for (size_t k = 0; k < 3; ++k) {
      long long index = static_cast<long long>(mesh.triangles[3 * t + k]) + 1;
      line += ' ';
      append_number(line, index);
      if (!normals) continue;
      line += "//";
      append_number(line, index);
    }
    line += '\n';
    file.write(line);
  }
}

// "l a b" per loose line segment.
void write_lines(const Mesh& mesh, AtomicFile& file) {
  std::string line;
  for (size_t e = 0; e < mesh.edge_count(); ++e) {
    line = "l";
    for (size_t k = 0; k < 2; ++k) {
      line += ' ';
      append_number(line, static_cast<long long>(mesh.edges[2 * e + k]) + 1);
    }
    line += '\n';
    file.write(line);
  }
}

}  // namespace

void write_obj(const Mesh& mesh, AtomicFile& file) {
  file.write(std::string_view("# isoform\n"));
  if (points_need_double(mesh))
    write_triples(file, "v", mesh.precise_points);
  else
    write_triples(file, "v", mesh.points);
  write_triples(file, "vn", mesh.normals);
  write_faces(mesh, file);
  write_lines(mesh, file);
}

}  // namespace isoform::meshio
