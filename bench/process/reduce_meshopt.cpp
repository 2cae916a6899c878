// The meshoptimizer peer as a user writes it: read the PLY, merge nothing,
// meshopt_simplify to the share asked (the relative error bound 1, the whole
// mesh's extent, so that the triangle target decides), drop the vertices no
// triangle uses, write a binary PLY.
//
// usage: reduce_meshopt IN.ply KEEP_FRACTION OUT.ply
#include <meshoptimizer.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

#include "ply_lite.h"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: reduce_meshopt IN.ply KEEP_FRACTION OUT.ply\n";
    return 2;
  }
  try {
    const process_bench::TriangleMesh in = process_bench::read_ply(argv[1]);
    const size_t vertices = in.points.size() / 3;
    const size_t target = 3 * size_t(std::llround(double(in.triangles.size() / 3) * std::atof(argv[2])));
    std::vector<uint32_t> indices(in.triangles.size());
    float error = 0;
    indices.resize(meshopt_simplify(indices.data(), in.triangles.data(), in.triangles.size(), in.points.data(),
                                    vertices, 3 * sizeof(float), target, 1.0f, 0, &error));
    std::vector<uint32_t> remap(vertices);
    const size_t kept = meshopt_optimizeVertexFetchRemap(remap.data(), indices.data(), indices.size(), vertices);
    process_bench::TriangleMesh out;
    out.points.resize(3 * kept);
    meshopt_remapVertexBuffer(out.points.data(), in.points.data(), vertices, 3 * sizeof(float), remap.data());
    out.triangles.resize(indices.size());
    meshopt_remapIndexBuffer(out.triangles.data(), indices.data(), indices.size(), remap.data());
    process_bench::write_ply(argv[3], out);
  } catch (const std::exception& error) {
    std::cerr << "reduce_meshopt: " << error.what() << '\n';
    return 1;
  }
  return 0;
}
