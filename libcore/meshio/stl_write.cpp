// Writing binary STL: the format 3-D printing and CAD tools expect. Each
// facet normal is computed from its triangle's corners (right-hand rule), as
// STL readers assume, rather than taken from the vertex normals.
#include <cmath>
#include <cstring>

#include "byte_order.h"
#include "formats.h"

namespace isoform::meshio {
namespace {

constexpr size_t kHeaderSize = 80;
constexpr size_t kTriangleSize = 50;

// Unit normal of triangle t; zero for a triangle without area.
void facet_normal(const Mesh& mesh, size_t t, float normal[3]) {
  const float* corner[3];
  for (size_t k = 0; k < 3; ++k) corner[k] = &mesh.points[3 * size_t(mesh.triangles[3 * t + k])];
  double u[3], v[3];
  for (size_t k = 0; k < 3; ++k) {
    u[k] = double(corner[1][k]) - corner[0][k];
    v[k] = double(corner[2][k]) - corner[0][k];
  }
  double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (size_t k = 0; k < 3; ++k) normal[k] = length > 0 ? float(n[k] / length) : 0.0f;
}

// The header must not begin with "solid", which would suggest ascii.
// save_mesh has checked that the triangle count fits in 32 bits.
void write_header(const Mesh& mesh, AtomicFile& file) {
  unsigned char header[kHeaderSize + 4] = {};
  std::memcpy(header, "isoform", 7);
  store_little_endian(header + kHeaderSize, mesh.triangle_count(), 4);
  file.write(header, sizeof header);
}

}  // namespace

void write_stl(const Mesh& mesh, AtomicFile& file) {
  write_header(mesh, file);
  unsigned char record[kTriangleSize] = {};  // the trailing attribute stays 0
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    float normal[3];
    facet_normal(mesh, t, normal);
    for (size_t k = 0; k < 3; ++k) store_float_le(record + 4 * k, normal[k]);
    for (size_t c = 0; c < 3; ++c) {
      const float* point = &mesh.points[3 * size_t(mesh.triangles[3 * t + c])];
      for (size_t k = 0; k < 3; ++k) store_float_le(record + 12 * (c + 1) + 4 * k, point[k]);
    }
    file.write(record, sizeof record);
  }
}

}  // namespace isoform::meshio
