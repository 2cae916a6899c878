// libFuzzer target: bytes as a .ply file, loaded through the C API; a small
// mesh that loads then goes through curvature, reduction and patches.
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  isoform_mesh* mesh = nullptr;
  if (isoform_mesh_load(isoform::fuzz::as_file(data, size, ".ply").c_str(), &mesh) != ISOFORM_OK) return 0;
  isoform::fuzz::exercise_mesh(mesh);
  isoform_mesh_free(mesh);
  return 0;
}
