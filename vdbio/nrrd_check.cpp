// A NRRD header read by isoform before Teem reads the file (see
// nrrd_check.h): Teem allocates the whole array from the header's sizes
// before it reads a byte of data, and follows any "data file" it names.
#include "nrrd_check.h"

#include <bzlib.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "gzip_inflate.h"
#include "input_file.h"
#include "libcore/errors.h"

namespace isoform::vdbio {

namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxHeader = size_t(1) << 20;  // far beyond any real header

// Teem's type names (nrrdType), by the bytes of one sample; 0 for "block".
uint64_t type_bytes(const std::string& type) {
  static const std::map<std::string, uint64_t> bytes = {
      {"signed char", 1}, {"int8", 1}, {"int8_t", 1}, {"uchar", 1}, {"unsigned char", 1}, {"uint8", 1},
      {"uint8_t", 1}, {"short", 2}, {"short int", 2}, {"signed short", 2}, {"signed short int", 2},
      {"int16", 2}, {"int16_t", 2}, {"ushort", 2}, {"unsigned short", 2}, {"unsigned short int", 2},
      {"uint16", 2}, {"uint16_t", 2}, {"int", 4}, {"signed int", 4}, {"int32", 4}, {"int32_t", 4},
      {"uint", 4}, {"unsigned int", 4}, {"uint32", 4}, {"uint32_t", 4}, {"longlong", 8}, {"long long", 8},
      {"long long int", 8}, {"signed long long", 8}, {"signed long long int", 8}, {"int64", 8},
      {"int64_t", 8}, {"ulonglong", 8}, {"unsigned long long", 8}, {"unsigned long long int", 8},
      {"uint64", 8}, {"uint64_t", 8}, {"float", 4}, {"double", 8}};
  const auto b = bytes.find(type);
  return b == bytes.end() ? 8 : b->second;  // Teem refuses unknown names itself
}

std::string trim(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  size_t first = 0;
  while (first < s.size() && std::isspace(static_cast<unsigned char>(s[first]))) ++first;
  return s.substr(first);
}

struct Header {
  std::map<std::string, std::string> fields;  // names without spaces, lower case
  uint64_t end = 0;                           // byte after the blank line
};

Header read_header(const std::string& path) {
  const std::string bytes = read_prefix(path, kMaxHeader);
  Header h;
  size_t at = 0;
  bool first = true;
  while (true) {
    const size_t eol = bytes.find('\n', at);
    if (eol == std::string::npos) {
      // Without a whole first line the magic was never seen: Teem would be
      // handed a file that is not NRRD (and leaks on those).
      if (first) throw FormatError(path + ": not a NRRD file (its first line is not NRRD0001 to NRRD0005)");
      if (bytes.size() >= kMaxHeader) throw FormatError(path + ": a NRRD header longer than 1 MiB");
      h.end = bytes.size();  // a detached header may end without a blank line
      return h;
    }
    std::string line = bytes.substr(at, eol - at);
    // Teem reads a header line as a C string: past a NUL byte the two
    // readers would see different fields.
    if (line.find('\0') != std::string::npos)
      throw FormatError(path + ": a NRRD header line holds a NUL byte");
    at = eol + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (first) {
      if (line.size() != 8 || line.compare(0, 7, "NRRD000") != 0 || line[7] < '1' || line[7] > '5')
        throw FormatError(path + ": not a NRRD file (its first line is not NRRD0001 to NRRD0005)");
      first = false;
      continue;
    }
    if (line.empty()) {
      h.end = at;
      return h;
    }
    if (line[0] == '#' || line.find(":=") != std::string::npos) continue;
    const size_t colon = line.find(": ");
    if (colon == std::string::npos) continue;  // Teem names the bad line
    std::string key;
    for (char c : line.substr(0, colon))
      if (c != ' ') key += char(std::tolower(static_cast<unsigned char>(c)));
    // Teem leaks what it has parsed when a per-axis field comes before the
    // dimension (and refuses the file then anyway).
    static const char* const kPerAxis[] = {"sizes",  "spacings", "thicknesses", "axismins", "axismaxs", "centers",
                                           "centerings", "labels", "units", "kinds", "spacedirections"};
    if (!h.fields.count("dimension") &&
        std::find(std::begin(kPerAxis), std::end(kPerAxis), key) != std::end(kPerAxis))
      throw FormatError(path + ": NRRD field \"" + line.substr(0, colon) + "\" comes before the dimension");
    h.fields[key] = trim(line.substr(colon + 2));
  }
}

uint64_t parse_count(const std::string& path, const std::string& field, const std::string& text) {
  uint64_t v = 0;
  if (text.empty() || text.size() > 19 || !std::all_of(text.begin(), text.end(), ::isdigit))
    throw FormatError(path + ": NRRD field \"" + field + "\" holds \"" + text + "\", not a count");
  for (char c : text) v = v * 10 + uint64_t(c - '0');
  return v;
}

// Teem's gzip reader leaks its stream when the data end early or do not
// decode, so the data are inflated here first: they must give at least the
// array's bytes, and no more is decoded than that, as Teem asks, so that
// Teem meets a gzip trailer (and its check) exactly where this check does.
void check_gzip_data(const std::string& path, const std::string& data, uint64_t start, uint64_t bytes) {
  const Inflated inflated = inflate_gzip(data, start, 0, bytes, nullptr);
  if (inflated.bytes < bytes)
    throw FormatError(path + ": NRRD gzip data give " + std::to_string(inflated.bytes) + " of the " +
                      std::to_string(bytes) + " bytes its sizes need" +
                      (inflated.damaged ? " (they do not decode)" : ""));
  if (inflated.damaged) throw FormatError(path + ": NRRD gzip data do not decode (a damaged stream or check sum)");
}

// Teem's bzip2 reader leaks its stream when the data do not decode, so
// they are decoded here first (and dropped), no further than the sizes need.
void check_bzip2_data(const std::string& path, const std::string& data, uint64_t start, uint64_t bytes) {
  std::ifstream in(data, std::ios::binary);
  in.seekg(std::streamoff(start));
  bz_stream z{};
  if (BZ2_bzDecompressInit(&z, 0, 0) != BZ_OK) throw FormatError(path + ": cannot start decoding its bzip2 data");
  std::vector<char> packed(size_t(1) << 16), plain(size_t(1) << 18);
  uint64_t got = 0;
  int status = BZ_OK;
  while (got < bytes && status == BZ_OK) {
    if (z.avail_in == 0) {
      in.read(packed.data(), std::streamsize(packed.size()));
      z.next_in = packed.data();
      z.avail_in = unsigned(in.gcount());
      if (z.avail_in == 0) break;
    }
    const unsigned room = unsigned(std::min<uint64_t>(plain.size(), bytes - got));
    z.next_out = plain.data();
    z.avail_out = room;
    status = BZ2_bzDecompress(&z);
    got += room - z.avail_out;
  }
  BZ2_bzDecompressEnd(&z);
  if (got < bytes)
    throw FormatError(path + ": NRRD bzip2 data give " + std::to_string(got) + " of the " + std::to_string(bytes) +
                      " bytes its sizes need" + (status < 0 ? " (they do not decode)" : ""));
}

}  // namespace

void check_nrrd_header(const std::string& path, uint64_t memory_budget) {
  const Header h = read_header(path);
  const auto field = [&](const std::string& key) {
    const auto f = h.fields.find(key);
    return f == h.fields.end() ? std::string() : f->second;
  };
  // The number of samples, refusing a product beyond 64 bits.
  std::istringstream sizes(field("sizes"));
  uint64_t count = 1;
  std::string size;
  while (sizes >> size) {
    const uint64_t n = parse_count(path, "sizes", size);
    if (n == 0 || count > UINT64_MAX / n) throw FormatError(path + ": NRRD sizes \"" + field("sizes") + "\"");
    count *= n;
  }
  const uint64_t sample = type_bytes(field("type"));
  if (count > UINT64_MAX / 16) throw FormatError(path + ": NRRD sizes \"" + field("sizes") + "\"");
  const uint64_t bytes = count * sample;
  // Where the data are: after the header, or in one other file.
  std::string data = path;
  uint64_t start = h.end;
  const std::string detached = !field("datafile").empty() ? field("datafile") : field("data file");
  if (!detached.empty()) {
    if (detached.rfind("LIST", 0) == 0 || detached.find('%') != std::string::npos)
      throw Unsupported(path + ": a NRRD whose data lie in several files; isoform reads one data file");
    const fs::path p(detached);
    data = p.is_absolute() ? detached : (fs::path(path).parent_path() / p).string();
    start = 0;
  }
  const uint64_t data_size = input_file_size(data);
  const std::string skip = field("byteskip");
  if (!skip.empty() && skip != "-1") start += parse_count(path, "byte skip", skip);
  const uint64_t present = data_size > start ? data_size - start : 0;
  // What those bytes can decode to, by the encoding.
  std::string encoding = field("encoding");
  std::transform(encoding.begin(), encoding.end(), encoding.begin(), ::tolower);
  static const char* const kEncodings[] = {"raw", "gzip", "gz", "bzip2", "bz2", "ascii", "text", "txt", "hex"};
  if (encoding.empty()) throw FormatError(path + ": a NRRD header without an encoding field");
  if (std::find(std::begin(kEncodings), std::end(kEncodings), encoding) == std::end(kEncodings))
    throw FormatError(path + ": NRRD encoding \"" + field("encoding") + "\" is not one isoform reads");
  uint64_t most = UINT64_MAX;  // bzip2: only the budget bounds it
  if (encoding == "raw") most = skip == "-1" ? data_size : present;
  if (encoding == "gzip" || encoding == "gz") most = present > UINT64_MAX / kDeflateRatio ? UINT64_MAX : present * kDeflateRatio;
  if (encoding == "ascii" || encoding == "text" || encoding == "txt") most = (present / 2 + 1) * sample;
  if (encoding == "hex") most = present / 2;
  if (bytes > most)
    throw FormatError(path + ": NRRD data of " + field("sizes") + " " + field("type") + " samples need " +
                      std::to_string(bytes) + " bytes, more than " + std::to_string(present) + " bytes of " +
                      encoding + " data in " + data + " can hold");
  // Teem's array and isoform's float copy of it.
  if (bytes > memory_budget || count * 4 > memory_budget - bytes)
    throw FormatError(path + ": NRRD data of " + field("sizes") + " samples would take " +
                      size_text(bytes + count * 4) + " in memory, beyond the budget of " +
                      size_text(memory_budget));
  if (encoding == "gzip" || encoding == "gz") check_gzip_data(path, data, start, bytes);
  if (encoding == "bzip2" || encoding == "bz2") check_bzip2_data(path, data, start, bytes);
}

}  // namespace isoform::vdbio
