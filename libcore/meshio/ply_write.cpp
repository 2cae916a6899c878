// Writing binary little-endian PLY: compact, exact for float32 points, and
// read by every mesh tool. Records are assembled byte by byte in little-endian
// order, so the file does not depend on the host.
#include <string>

#include "byte_order.h"
#include "formats.h"

namespace isoform::meshio {
namespace {

std::string header_text(const Mesh& mesh) {
  bool normals = !mesh.normals.empty();
  bool parts = !mesh.parts.empty();
  std::string text =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment isoform\n";
  text += "element vertex " + std::to_string(mesh.vertex_count()) + "\n";
  text += "property float x\nproperty float y\nproperty float z\n";
  if (normals) text += "property float nx\nproperty float ny\nproperty float nz\n";
  text += "element face " + std::to_string(mesh.triangle_count()) + "\n";
  text += "property list uchar int vertex_indices\n";
  if (parts) text += "property int part\n";
  text += "end_header\n";
  return text;
}

void write_vertices(const Mesh& mesh, AtomicFile& file) {
  bool normals = !mesh.normals.empty();
  unsigned char record[24];  // x y z, then nx ny nz when present
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    for (size_t k = 0; k < 3; ++k) store_float_le(record + 4 * k, mesh.points[3 * v + k]);
    if (normals) {
      for (size_t k = 0; k < 3; ++k) store_float_le(record + 12 + 4 * k, mesh.normals[3 * v + k]);
    }
    file.write(record, normals ? 24 : 12);
  }
}

void write_faces(const Mesh& mesh, AtomicFile& file) {
  bool parts = !mesh.parts.empty();
  unsigned char record[17];  // count 3, three indices, then the part when present
  record[0] = 3;
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (size_t k = 0; k < 3; ++k) store_int32_le(record + 1 + 4 * k, mesh.triangles[3 * t + k]);
    if (parts) store_int32_le(record + 13, mesh.parts[t]);
    file.write(record, parts ? 17 : 13);
  }
}

}  // namespace

void write_ply(const Mesh& mesh, AtomicFile& file) {
  file.write(header_text(mesh));
  write_vertices(mesh, file);
  write_faces(mesh, file);
}

}  // namespace isoform::meshio
