// Writing binary little-endian PLY: compact, exact for float32 points, and
// read by every mesh tool. Records are assembled byte by byte in little-endian
// order, so the file does not depend on the host.
#include <string>

#include "byte_order.h"
#include "formats.h"

namespace isoform::meshio {
namespace {

// Per-vertex curvature (Chapter 4), in this order after the normals.
const char* const kCurvatureProperties[] = {"k1",  "k2",  "mean", "gauss", "absolute", "d1x",
                                            "d1y", "d1z", "d2x",  "d2y",   "d2z"};
constexpr size_t kCurvatureCount = 11;

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
  if (!mesh.curvature.empty())
    for (const char* name : kCurvatureProperties) text += std::string("property float ") + name + "\n";
  if (!mesh.curvature.empty()) text += "property uchar curvature_flags\n";
  if (!mesh.colors.empty())
    text += "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n";
  text += "element face " + std::to_string(mesh.triangle_count()) + "\n";
  text += "property list uchar int vertex_indices\n";
  if (parts) text += "property int part\n";
  text += "end_header\n";
  return text;
}

// The curvature values of vertex v in kCurvatureProperties order.
void curvature_record(const VertexCurvature& c, size_t v, float out[kCurvatureCount]) {
  const float head[5] = {c.k1[v], c.k2[v], c.mean[v], c.gauss[v], c.absolute[v]};
  for (size_t k = 0; k < 5; ++k) out[k] = head[k];
  for (size_t k = 0; k < 3; ++k) {
    out[5 + k] = c.d1[3 * v + k];
    out[8 + k] = c.d2[3 * v + k];
  }
}

void write_vertices(const Mesh& mesh, AtomicFile& file) {
  const bool normals = !mesh.normals.empty(), curvature = !mesh.curvature.empty(), colors = !mesh.colors.empty();
  // x y z, then nx ny nz, the curvature and its flags, and the colour, each when present
  unsigned char record[24 + 4 * kCurvatureCount + 1 + 4];
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    size_t at = 0;
    for (size_t k = 0; k < 3; ++k, at += 4) store_float_le(record + at, mesh.points[3 * v + k]);
    if (normals)
      for (size_t k = 0; k < 3; ++k, at += 4) store_float_le(record + at, mesh.normals[3 * v + k]);
    if (curvature) {
      float values[kCurvatureCount];
      curvature_record(mesh.curvature, v, values);
      for (float x : values) store_float_le(record + at, x), at += 4;
      record[at++] = mesh.curvature.flags[v];
    }
    if (colors)
      for (size_t k = 0; k < 4; ++k) record[at++] = mesh.colors[4 * v + k];
    file.write(record, at);
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
