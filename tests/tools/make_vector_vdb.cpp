// Writes a small OpenVDB file whose only grid is a vector grid ("velocity",
// vec3s), which the C API can read but not contour, and cannot write. The
// add-on tests use it to check that the library's message reaches the user.
//
// usage: make_vector_vdb OUT.vdb
#include <cstdio>
#include <exception>

#include <openvdb/openvdb.h>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_vector_vdb OUT.vdb\n");
    return 2;
  }
  try {
    openvdb::initialize();
    auto grid = openvdb::Vec3SGrid::create(openvdb::Vec3f(0.0f));
    grid->setName("velocity");
    auto accessor = grid->getAccessor();
    // A 4^3 block of unit vectors: enough active voxels to be a real grid.
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) accessor.setValue(openvdb::Coord(i, j, k), openvdb::Vec3f(1, 0, 0));
    openvdb::io::File(argv[1]).write({grid});
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "make_vector_vdb: %s\n", error.what());
    return 1;
  }
}
