#include "ply_lite.h"

#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace process_bench {
namespace {

int type_size(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  throw std::runtime_error("unknown PLY type " + type);
}

double read_value(const char* p, const std::string& type) {
  if (type == "float" || type == "float32") { float v; std::memcpy(&v, p, 4); return v; }
  if (type == "double" || type == "float64") { double v; std::memcpy(&v, p, 8); return v; }
  if (type == "uchar" || type == "uint8") return static_cast<unsigned char>(*p);
  if (type == "char" || type == "int8") return static_cast<signed char>(*p);
  if (type == "int" || type == "int32") { int32_t v; std::memcpy(&v, p, 4); return v; }
  if (type == "uint" || type == "uint32") { uint32_t v; std::memcpy(&v, p, 4); return v; }
  if (type == "short" || type == "int16") { int16_t v; std::memcpy(&v, p, 2); return v; }
  uint16_t v;
  std::memcpy(&v, p, 2);
  return v;
}

struct Property {
  std::string name, type, count_type;  // count_type: lists only
};

}  // namespace

TriangleMesh read_ply(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string line;
  size_t vertices = 0, faces = 0;
  std::vector<Property> vertex_props, face_props;
  std::vector<Property>* current = nullptr;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "format" && line.find("binary_little_endian") == std::string::npos)
      throw std::runtime_error(path + ": not binary little-endian PLY");
    if (word == "element") {
      std::string name;
      size_t count = 0;
      words >> name >> count;
      current = name == "vertex" ? &vertex_props : name == "face" ? &face_props : nullptr;
      if (!current) throw std::runtime_error(path + ": unexpected element " + name);
      (name == "vertex" ? vertices : faces) = count;
    }
    if (word == "property" && current) {
      Property p;
      words >> p.type;
      if (p.type == "list") words >> p.count_type >> p.type;
      words >> p.name;
      current->push_back(p);
    }
    if (word == "end_header") break;
  }
  TriangleMesh mesh;
  mesh.points.resize(3 * vertices);
  size_t stride = 0;
  for (const Property& p : vertex_props) stride += size_t(type_size(p.type));
  std::vector<char> block(stride * vertices);
  in.read(block.data(), std::streamsize(block.size()));
  if (!in) throw std::runtime_error(path + ": vertex data cut short");
  for (size_t v = 0; v < vertices; ++v) {
    const char* p = block.data() + v * stride;
    for (const Property& prop : vertex_props) {
      const int axis = prop.name == "x" ? 0 : prop.name == "y" ? 1 : prop.name == "z" ? 2 : -1;
      if (axis >= 0) mesh.points[3 * v + size_t(axis)] = float(read_value(p, prop.type));
      p += type_size(prop.type);
    }
  }
  mesh.triangles.reserve(3 * faces);
  std::vector<char> bytes(64);
  for (size_t f = 0; f < faces; ++f)
    for (const Property& prop : face_props) {
      if (prop.count_type.empty()) {
        in.read(bytes.data(), type_size(prop.type));
        continue;
      }
      in.read(bytes.data(), type_size(prop.count_type));
      const size_t n = size_t(read_value(bytes.data(), prop.count_type));
      if (n != 3 || !in) throw std::runtime_error(path + ": a face that is not a triangle");
      in.read(bytes.data(), 3 * type_size(prop.type));
      for (int k = 0; k < 3; ++k)
        mesh.triangles.push_back(uint32_t(read_value(bytes.data() + k * type_size(prop.type), prop.type)));
    }
  if (!in) throw std::runtime_error(path + ": face data cut short");
  return mesh;
}

void write_ply(const std::string& path, const TriangleMesh& mesh) {
  const size_t vertices = mesh.points.size() / 3, triangles = mesh.triangles.size() / 3;
  const bool normals = mesh.normals.size() == mesh.points.size();
  std::ostringstream header;
  header << "ply\nformat binary_little_endian 1.0\nelement vertex " << vertices
         << "\nproperty float x\nproperty float y\nproperty float z\n";
  if (normals) header << "property float nx\nproperty float ny\nproperty float nz\n";
  header << "element face " << triangles << "\nproperty list uchar int vertex_indices\nend_header\n";
  std::vector<char> body;
  body.reserve(vertices * (normals ? 24 : 12) + triangles * 13);
  const auto put = [&body](const void* p, size_t n) {
    body.insert(body.end(), static_cast<const char*>(p), static_cast<const char*>(p) + n);
  };
  for (size_t v = 0; v < vertices; ++v) {
    put(&mesh.points[3 * v], 12);
    if (normals) put(&mesh.normals[3 * v], 12);
  }
  for (size_t t = 0; t < triangles; ++t) {
    const unsigned char three = 3;
    put(&three, 1);
    put(&mesh.triangles[3 * t], 12);
  }
  std::ofstream out(path, std::ios::binary);
  const std::string text = header.str();
  out.write(text.data(), std::streamsize(text.size()));
  out.write(body.data(), std::streamsize(body.size()));
  if (!out) throw std::runtime_error(path + ": cannot write");
}

}  // namespace process_bench
