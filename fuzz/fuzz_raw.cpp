// libFuzzer target: a headerless raw scan. The first 12 bytes choose the
// layout the user would give (dims 1-32 each, sample type, byte order,
// header bytes 0-255); the rest is the file.
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 12) return 0;
  isoform_raw_options options;
  isoform_raw_options_default(&options);
  for (int a = 0; a < 3; ++a) options.dims[a] = 1 + data[a] % 32;
  options.scalar_type = data[3] % 8;
  options.big_endian = data[4] & 1;
  options.header_bytes = data[5];
  for (int a = 0; a < 3; ++a) options.spacing[a] = 0.25 * (1 + data[6 + a] % 8);
  isoform_volume* volume = nullptr;
  const std::string path = isoform::fuzz::as_file(data + 12, size - 12, ".raw");
  if (isoform_volume_open_raw(path.c_str(), &options, &volume) != ISOFORM_OK) return 0;
  isoform::fuzz::exercise_volume(volume);
  isoform_volume_free(volume);
  return 0;
}
