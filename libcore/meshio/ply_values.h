// The values of a PLY body, one at a time in file order, in each encoding.
// Every value comes out as a double, which holds all PLY scalar types exactly
// (32-bit integers included), so the reader needs one code path per element
// rather than one per type.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "ply_header.h"
#include "text_cursor.h"

namespace isoform::meshio {

// binary_little_endian and binary_big_endian.
class PlyBinaryValues {
 public:
  PlyBinaryValues(std::string_view bytes, size_t offset, bool big_endian)
      : bytes_(bytes), pos_(offset), big_endian_(big_endian) {}

  // Reads the next value of type; false when the data end first.
  bool read(PlyType type, double& out);
  // Why the last read failed.
  std::string problem() const { return "the file ends early (truncated?)"; }
  // Nothing but line ends or spaces left?
  bool at_end() const;

 private:
  std::string_view bytes_;
  size_t pos_;
  bool big_endian_;
};

// ascii: whitespace-separated numbers; line breaks carry no meaning.
class PlyAsciiValues {
 public:
  PlyAsciiValues(std::string_view text, size_t offset) : cursor_(text, offset) {}

  // Reads the next value of type; false at the end of the text or when the
  // token is not a number of that type.
  bool read(PlyType type, double& out);
  // Why the last read failed, with the line.
  std::string problem() const { return problem_; }
  // Nothing but whitespace left?
  bool at_end() const {
    TextCursor rest = cursor_;
    return rest.token().empty();
  }

 private:
  TextCursor cursor_;
  std::string problem_;
};

}  // namespace isoform::meshio
