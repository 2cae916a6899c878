// save_mesh and load_mesh: the checks made once at entry, and the choice of
// format by extension.
#include "meshio.h"

#include <cstdint>
#include <filesystem>

#include "../errors.h"
#include "atomic_file.h"
#include "file_bytes.h"
#include "formats.h"

namespace isoform {
namespace {

enum class Format { ply, obj, stl };

Format format_of(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
  if (extension == ".ply") return Format::ply;
  if (extension == ".obj") return Format::obj;
  if (extension == ".stl") return Format::stl;
  throw InvalidArgument(path + ": unknown mesh file extension \"" + extension +
                        "\" (use .ply, .obj or .stl)");
}

// The writers trust these, so a bad mesh fails here rather than as a file
// with dangling indices.
void check_sizes(const Mesh& mesh, const std::string& path) {
  auto refuse = [&](const std::string& what) {
    throw InvalidArgument("cannot save " + path + ": " + what);
  };
  if (mesh.points.size() % 3 != 0) refuse("the points are not whole triples");
  if (mesh.triangles.size() % 3 != 0) refuse("the triangles are not whole triples");
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.points.size()) {
    refuse("there are " + std::to_string(mesh.normals.size() / 3) + " normals for " +
           std::to_string(mesh.vertex_count()) + " vertices");
  }
  if (!mesh.curvature.empty() && mesh.curvature.k1.size() != mesh.vertex_count())
    refuse("the curvature arrays do not match the vertices");
  if (!mesh.colors.empty() && mesh.colors.size() != 4 * mesh.vertex_count()) {
    refuse("there are " + std::to_string(mesh.colors.size() / 4) + " colours for " +
           std::to_string(mesh.vertex_count()) + " vertices");
  }
  if (mesh.edges.size() % 2 != 0) refuse("the edges are not whole pairs");
  if (!mesh.parts.empty() && mesh.parts.size() != mesh.triangle_count()) {
    refuse("there are " + std::to_string(mesh.parts.size()) + " parts for " +
           std::to_string(mesh.triangle_count()) + " triangles");
  }
}

void check_indices(const std::vector<int32_t>& indices, size_t per_item, const char* item,
                   size_t vertices, const std::string& path) {
  for (size_t i = 0; i < indices.size(); ++i) {
    int32_t vertex = indices[i];
    if (vertex < 0 || size_t(vertex) >= vertices) {
      throw InvalidArgument("cannot save " + path + ": " + item + " " + std::to_string(i / per_item) +
                            " refers to vertex " + std::to_string(vertex) + " but there are " +
                            std::to_string(vertices) + " vertices");
    }
  }
}

// Binary STL counts triangles in 32 bits.
void check_format_limits(const Mesh& mesh, Format format, const std::string& path) {
  if (format == Format::stl && mesh.triangle_count() > UINT32_MAX) {
    throw InvalidArgument("cannot save " + path + ": " + std::to_string(mesh.triangle_count()) +
                          " triangles are more than STL can count");
  }
}

// NOTE: some writers fill the normal slots with zeros when they have none;
// taken as given, such normals made every fit that leans on them fall back
// and the reduction's error grow by half. A file with a zero normal is read
// as one without normals, which are then estimated.
void drop_zero_normals(Mesh& mesh) {
  for (size_t i = 0; i + 2 < mesh.normals.size(); i += 3)
    if (mesh.normals[i] == 0 && mesh.normals[i + 1] == 0 && mesh.normals[i + 2] == 0) {
      mesh.normals.clear();
      return;
    }
}

Mesh read_by_format(const std::string& path) {
  Format format = format_of(path);
  std::string bytes = meshio::read_file_bytes(path);
  switch (format) {
    case Format::ply: return meshio::read_ply(bytes, path);
    case Format::obj: return meshio::read_obj(bytes, path);
    case Format::stl: return meshio::read_stl(bytes, path);
  }
  return Mesh();
}

}  // namespace

void save_mesh(const Mesh& mesh, const std::string& path) { save_mesh(mesh, path, Progress(nullptr)); }

void save_mesh(const Mesh& mesh, const std::string& path, const Progress& progress) {
  Format format = format_of(path);
  check_sizes(mesh, path);
  check_indices(mesh.triangles, 3, "triangle", mesh.vertex_count(), path);
  check_indices(mesh.edges, 2, "edge", mesh.vertex_count(), path);
  check_format_limits(mesh, format, path);
  meshio::AtomicFile file(path, [&progress] { return progress.cancelled(); });
  switch (format) {
    case Format::ply: meshio::write_ply(mesh, file); break;
    case Format::obj: meshio::write_obj(mesh, file); break;
    case Format::stl: meshio::write_stl(mesh, file); break;
  }
  file.commit();
}

Mesh load_mesh(const std::string& path) {
  Mesh mesh = read_by_format(path);
  drop_zero_normals(mesh);
  return mesh;
}

}  // namespace isoform
