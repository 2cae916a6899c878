// Tokens and numbers for the ascii formats (PLY, OBJ, STL). Numbers are read
// with std::from_chars: independent of the locale, and exact for float, so a
// float written in its shortest form reads back to the same bits.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace isoform::meshio {

class TextCursor {
 public:
  explicit TextCursor(std::string_view text, size_t offset = 0) : text_(text), pos_(offset) {}

  // The next whitespace-separated token, across line ends; empty at the end.
  std::string_view token();
  // The next token on the current line; empty at the end of the line.
  std::string_view token_on_line();
  // Moves to the start of the next line; false if there is none.
  bool next_line();
  // The 1-based line the cursor is on. Counts from the start of the text, so
  // meant for error messages only.
  size_t line() const;

 private:
  std::string_view text_;
  size_t pos_;
};

// Each parses the whole token as a number and returns false if it is not
// one (or does not fit). A leading '+' is accepted.
bool parse_number(std::string_view token, float& out);
bool parse_number(std::string_view token, double& out);
bool parse_number(std::string_view token, long long& out);

// What is wrong with a token that parse_number(token, float&) refused:
// "\"abc\" is not a number" or "\"1e40\" is beyond the range of a float".
std::string not_a_float(std::string_view token);

// Whether token equals keyword, ignoring ASCII case ("SOLID" is "solid").
bool same_keyword(std::string_view token, std::string_view keyword);

}  // namespace isoform::meshio
