// Writing binary little-endian PLY: compact, exact for float32 points, and
// read by every mesh tool. Records are assembled byte by byte in little-endian
// order, so the file does not depend on the host.
//
// A vertex record is x y z followed by the optional vertex properties that
// the mesh carries (vertex_properties below): each is a group of scalar PLY
// properties read from one array of the mesh, written only when that array
// is not empty. A new per-vertex array is one more entry in that list.
#include <string>
#include <vector>

#include "byte_order.h"
#include "formats.h"

namespace isoform::meshio {
namespace {

// A group of per-vertex PLY properties stored together in one mesh array.
struct VertexProperty {
  const char* type;                 // PLY scalar type: "float" or "uchar"
  std::vector<const char*> names;   // one PLY property per component
  const void* data;                 // names.size() values per vertex, or null
  size_t size() const { return std::string(type) == "float" ? 4 : 1; }
};

std::vector<VertexProperty> vertex_properties(const Mesh& mesh) {
  std::vector<VertexProperty> out;
  if (!mesh.normals.empty()) out.push_back({"float", {"nx", "ny", "nz"}, mesh.normals.data()});
  // Per-vertex curvature (Chapter 4), after the normals.
  const VertexCurvature& c = mesh.curvature;
  if (!c.empty()) {
    out.push_back({"float", {"k1"}, c.k1.data()});
    out.push_back({"float", {"k2"}, c.k2.data()});
    out.push_back({"float", {"mean"}, c.mean.data()});
    out.push_back({"float", {"gauss"}, c.gauss.data()});
    out.push_back({"float", {"absolute"}, c.absolute.data()});
    out.push_back({"float", {"d1x", "d1y", "d1z"}, c.d1.data()});
    out.push_back({"float", {"d2x", "d2y", "d2z"}, c.d2.data()});
    out.push_back({"uchar", {"curvature_flags"}, c.flags.data()});
  }
  if (!mesh.colors.empty())
    out.push_back({"uchar", {"red", "green", "blue", "alpha"}, mesh.colors.data()});
  return out;
}

std::string header_text(const Mesh& mesh, const std::vector<VertexProperty>& properties, bool doubles) {
  bool parts = !mesh.parts.empty();
  std::string text =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment isoform\n";
  text += "element vertex " + std::to_string(mesh.vertex_count()) + "\n";
  text += doubles ? "property double x\nproperty double y\nproperty double z\n"
                 : "property float x\nproperty float y\nproperty float z\n";
  for (const VertexProperty& p : properties)
    for (const char* name : p.names) text += std::string("property ") + p.type + " " + name + "\n";
  text += "element face " + std::to_string(mesh.triangle_count()) + "\n";
  text += "property list uchar int vertex_indices\n";
  if (parts) text += "property int part\n";
  if (!mesh.edges.empty()) {
    text += "element edge " + std::to_string(mesh.edge_count()) + "\n";
    text += "property int vertex1\nproperty int vertex2\n";
  }
  text += "end_header\n";
  return text;
}

// Appends vertex v's components of p to record at offset; returns the new offset.
size_t store_property(const VertexProperty& p, size_t v, unsigned char* record, size_t offset) {
  const size_t n = p.names.size();
  for (size_t k = 0; k < n; ++k) {
    if (p.size() == 4) {
      store_float_le(record + offset, static_cast<const float*>(p.data)[n * v + k]);
    } else {
      record[offset] = static_cast<const unsigned char*>(p.data)[n * v + k];
    }
    offset += p.size();
  }
  return offset;
}

void write_vertices(const Mesh& mesh, const std::vector<VertexProperty>& properties, bool doubles,
                    AtomicFile& file) {
  const size_t point_size = doubles ? 24 : 12;
  size_t record_size = point_size;
  for (const VertexProperty& p : properties) record_size += p.size() * p.names.size();
  std::vector<unsigned char> record(record_size);
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    for (size_t k = 0; k < 3; ++k) {
      if (doubles)
        store_double_le(record.data() + 8 * k, mesh.precise_points[3 * v + k]);
      else
        store_float_le(record.data() + 4 * k, mesh.points[3 * v + k]);
    }
    size_t offset = point_size;
    for (const VertexProperty& p : properties) offset = store_property(p, v, record.data(), offset);
    file.write(record.data(), record_size);
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

void write_edges(const Mesh& mesh, AtomicFile& file) {
  unsigned char record[8];
  for (size_t e = 0; e < mesh.edge_count(); ++e) {
    store_int32_le(record, mesh.edges[2 * e]);
    store_int32_le(record + 4, mesh.edges[2 * e + 1]);
    file.write(record, 8);
  }
}

}  // namespace

void write_ply(const Mesh& mesh, AtomicFile& file) {
  const std::vector<VertexProperty> properties = vertex_properties(mesh);
  const bool doubles = points_need_double(mesh);
  file.write(header_text(mesh, properties, doubles));
  write_vertices(mesh, properties, doubles, file);
  write_faces(mesh, file);
  write_edges(mesh, file);
}

}  // namespace isoform::meshio
