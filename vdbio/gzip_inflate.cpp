// Bounded gzip inflation (see gzip_inflate.h).
#include "gzip_inflate.h"

#include <zlib.h>

#include <algorithm>
#include <fstream>
#include <vector>

#include "libcore/errors.h"

namespace isoform::vdbio {

Inflated inflate_gzip(const std::string& file, uint64_t start, uint64_t skip, uint64_t bytes,
                      const std::function<void(const unsigned char*, size_t)>& sink) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(file + ": cannot be read");
  in.seekg(std::streamoff(start));
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK) throw IoError(file + ": cannot start inflating its gzip data");
  std::vector<unsigned char> packed(size_t(1) << 16), plain(size_t(1) << 18);
  const uint64_t total = skip + bytes;
  uint64_t decoded = 0;
  int status = Z_OK;
  while (decoded < total) {
    if (z.avail_in == 0) {
      in.read(reinterpret_cast<char*>(packed.data()), std::streamsize(packed.size()));
      z.next_in = packed.data();
      z.avail_in = uInt(in.gcount());
      if (z.avail_in == 0) break;
    }
    // No more output than asked for: a reader that checks the trailer
    // meets it exactly where this one does.
    const uInt room = uInt(std::min<uint64_t>(plain.size(), total - decoded));
    z.next_out = plain.data();
    z.avail_out = room;
    status = inflate(&z, Z_NO_FLUSH);
    const uint64_t got = room - z.avail_out;
    // The part of this piece that lies past `skip`.
    const uint64_t first = decoded < skip ? std::min(got, skip - decoded) : 0;
    if (sink && got > first) sink(plain.data() + first, size_t(got - first));
    decoded += got;
    if (status == Z_STREAM_END) {
      if (inflateReset(&z) != Z_OK) break;
    } else if (status != Z_OK && status != Z_BUF_ERROR) {
      break;
    }
  }
  inflateEnd(&z);
  Inflated result;
  result.bytes = decoded > skip ? decoded - skip : 0;
  result.damaged = status < 0 && status != Z_BUF_ERROR;
  return result;
}

}  // namespace isoform::vdbio
