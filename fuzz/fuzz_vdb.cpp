// libFuzzer target: bytes as a .vdb file, opened through the C API, each
// grid described and the small scalar ones contoured.
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  isoform::fuzz::fuzz_volume_file(data, size, ".vdb");
  return 0;
}
