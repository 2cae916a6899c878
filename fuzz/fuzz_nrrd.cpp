// libFuzzer target: bytes as a .nrrd file, opened through the C API, each
// grid described and the small scalar ones contoured.
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  isoform_volume* volume = nullptr;
  if (isoform_volume_open(isoform::fuzz::as_file(data, size, ".nrrd").c_str(), &volume) != ISOFORM_OK) return 0;
  isoform::fuzz::exercise_volume(volume);
  isoform_volume_free(volume);
  return 0;
}
