// A small binary PLY reader and writer for the peers' programs: what a user
// of meshoptimizer or OpenVDB writes around the library to read and write a
// mesh file. Points as float x y z; triangles as int indices. Other vertex
// and face properties are skipped when read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace process_bench {

struct TriangleMesh {
  std::vector<float> points;        // x y z per vertex
  std::vector<float> normals;       // nx ny nz per vertex, or empty
  std::vector<uint32_t> triangles;  // three per triangle
};

// Reads a binary little-endian PLY of triangles; throws std::runtime_error
// naming the file on anything else.
TriangleMesh read_ply(const std::string& path);

// Writes binary little-endian PLY: x y z (nx ny nz when given), then
// vertex_indices as uchar count and int indices.
void write_ply(const std::string& path, const TriangleMesh& mesh);

}  // namespace process_bench
