// libFuzzer target: bytes as a .obj file, loaded through the C API; a small
// mesh that loads then goes through curvature, reduction and patches.
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  isoform::fuzz::fuzz_mesh_file(data, size, ".obj");
  return 0;
}
