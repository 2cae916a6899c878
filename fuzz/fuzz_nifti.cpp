// libFuzzer target: bytes as a .nii file (gzip or not: the reader looks),
// opened through the C API with no volume index, or volume 0 or 1 of a 4-D
// file (chosen by the input's length), each grid described and the small
// ones contoured.
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  isoform_open_options options;
  isoform_open_options_default(&options);
  options.volume = int(size % 3) - 1;
  isoform::fuzz::fuzz_volume_file(data, size, ".nii", &options);
  return 0;
}
