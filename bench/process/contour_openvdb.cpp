// The OpenVDB peer as a user writes it: read the grid, volumeToMesh
// (adaptivity 0), write a binary PLY of triangles (each quad split in two).
//
// usage: contour_openvdb IN.vdb ISOVALUE OUT.ply [GRID]
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <cstdlib>
#include <iostream>

#include "ply_lite.h"

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: contour_openvdb IN.vdb ISOVALUE OUT.ply [GRID]\n";
    return 2;
  }
  try {
    openvdb::initialize();
    openvdb::io::File file(argv[1]);
    file.open(false);
    openvdb::GridBase::Ptr base;
    if (argc > 4) {
      base = file.readGrid(argv[4]);
    } else {
      for (auto it = file.beginName(); it != file.endName() && !base; ++it) {
        openvdb::GridBase::Ptr grid = file.readGrid(it.gridName());
        if (grid->isType<openvdb::FloatGrid>()) base = grid;
      }
    }
    file.close();
    openvdb::FloatGrid::Ptr grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
    if (!grid) throw std::runtime_error(std::string(argv[1]) + ": no float grid");
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*grid, points, triangles, quads, std::atof(argv[2]), 0.0);
    process_bench::TriangleMesh mesh;
    mesh.points.resize(3 * points.size());
    for (size_t i = 0; i < points.size(); ++i)
      for (int a = 0; a < 3; ++a) mesh.points[3 * i + size_t(a)] = points[i][a];
    mesh.triangles.reserve(3 * (triangles.size() + 2 * quads.size()));
    for (const auto& t : triangles) mesh.triangles.insert(mesh.triangles.end(), {t[0], t[1], t[2]});
    for (const auto& q : quads)
      mesh.triangles.insert(mesh.triangles.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    process_bench::write_ply(argv[3], mesh);
  } catch (const std::exception& error) {
    std::cerr << "contour_openvdb: " << error.what() << '\n';
    return 1;
  }
  return 0;
}
