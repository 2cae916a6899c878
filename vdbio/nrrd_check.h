// A NRRD file's header checked before Teem reads it. Teem allocates the
// whole array from the header's "sizes" before it reads any data, and reads
// whatever "data file" names, so isoform first refuses a header whose
// samples cannot come from the data present (raw bytes short of the size,
// gzip data that cannot expand that far: deflate's ratio is at most 1032
// to 1, text with fewer numbers than samples), whose array would pass the
// memory budget, or whose data lie in several files; gzip data that end
// early or do not decode, and bzip2 data that do not give the array's bytes
// (Teem's gzip and bzip2 readers leak their streams on them); and
// a first line that is not NRRD0001 to NRRD0005 (Teem leaks a little when
// it refuses one).
#pragma once

#include <cstdint>
#include <string>

namespace isoform::vdbio {

// Throws FormatError or Unsupported naming the file, IoError if it or its
// data file is missing or unreadable.
void check_nrrd_header(const std::string& path, uint64_t memory_budget);

}  // namespace isoform::vdbio
