// gzip data inflated with a bound: a reader asks for the decoded bytes it
// needs and never gets more, so a small file cannot make isoform decode (or
// allocate) more than its header has been checked to promise.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace isoform::vdbio {

// deflate's largest expansion: n bytes of gzip data decode to at most this
// many times n bytes, whatever they hold.
constexpr uint64_t kDeflateRatio = 1032;

struct Inflated {
  uint64_t bytes = 0;    // decoded bytes handed to the sink (past `skip`)
  bool damaged = false;  // the data stopped decoding (a bad stream or check sum)
};

// Inflates the gzip (or zlib) data of `file` from byte `start` on, as gzip reads them
// (several members after one another are read on): decoded bytes
// [skip, skip + bytes) go to `sink` in pieces, the first `skip` are
// dropped, and decoding stops there. A null sink only counts. Throws
// IoError if the file cannot be read.
Inflated inflate_gzip(const std::string& file, uint64_t start, uint64_t skip, uint64_t bytes,
                      const std::function<void(const unsigned char*, size_t)>& sink);

}  // namespace isoform::vdbio
