// Writes a small OpenVDB file holding one vec3s grid "velocity" and nothing
// else: input for the CLI tests of commands that need a scalar grid.
//   make_vector_vdb OUT.vdb
#include <openvdb/openvdb.h>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_vector_vdb OUT.vdb\n";
    return 2;
  }
  openvdb::initialize();
  auto grid = openvdb::Vec3SGrid::create();
  grid->setName("velocity");
  for (int i = 0; i < 10; ++i) grid->tree().setValue(openvdb::Coord(i, 0, 0), openvdb::Vec3s(1, 2, 3));
  openvdb::io::File(argv[1]).write({grid});
  return 0;
}
