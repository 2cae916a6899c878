// The OpenMesh peer as a user writes it: read the PLY with OpenMesh's IO,
// Decimater with quadrics (no error bound, so the triangle target decides)
// and normal-flip refusal (its default 90 degrees), to the share asked,
// garbage collection, write a binary PLY with OpenMesh's IO.
//
// usage: reduce_openmesh IN.ply KEEP_FRACTION OUT.ply
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <cmath>
#include <cstdlib>
#include <iostream>

using Mesh = OpenMesh::TriMesh_ArrayKernelT<>;

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: reduce_openmesh IN.ply KEEP_FRACTION OUT.ply\n";
    return 2;
  }
  Mesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, argv[1])) {
    std::cerr << "reduce_openmesh: cannot read " << argv[1] << '\n';
    return 1;
  }
  const size_t target = size_t(std::llround(double(mesh.n_faces()) * std::atof(argv[2])));
  mesh.request_face_normals();
  mesh.update_face_normals();
  OpenMesh::Decimater::DecimaterT<Mesh> decimater(mesh);
  OpenMesh::Decimater::ModQuadricT<Mesh>::Handle quadric;
  OpenMesh::Decimater::ModNormalFlippingT<Mesh>::Handle flipping;
  decimater.add(quadric);
  decimater.add(flipping);
  decimater.module(quadric).unset_max_err();
  decimater.initialize();
  decimater.decimate_to_faces(0, target);
  mesh.garbage_collection();
  if (!OpenMesh::IO::write_mesh(mesh, argv[3], OpenMesh::IO::Options::Binary)) {
    std::cerr << "reduce_openmesh: cannot write " << argv[3] << '\n';
    return 1;
  }
  return 0;
}
