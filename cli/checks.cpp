// Checks of option values shared by the commands (see cli.h).
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

#include "cli.h"

namespace isoform::cli {

CLI::Validator non_negative_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const char* begin = text.c_str();
        char* end = nullptr;
        errno = 0;
        const double value = std::strtod(begin, &end);
        if (end == begin || *end != '\0') return "'" + text + "' is not a number";
        if (!std::isfinite(value) || errno == ERANGE) return "'" + text + "' is not a finite number";
        if (value < 0) return "'" + text + "' is negative; write 0 or more";
        return "";
      },
      "NUMBER >= 0");
}

unsigned long long parse_byte_size(const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double number = std::strtod(begin, &end);
  if (end == begin || !std::isfinite(number) || number <= 0 || errno == ERANGE)
    throw Failure("--memory: '" + text + "' is not a size such as 512M or 2G", 2);
  std::string unit(end);
  for (char& c : unit) c = char(std::toupper(static_cast<unsigned char>(c)));
  if (unit.size() > 1 && unit.substr(unit.size() - 1) == "B") unit.pop_back();
  if (unit.size() > 1 && unit.substr(unit.size() - 1) == "I") unit.pop_back();
  const std::string units = "KMGT";
  double bytes = number;
  if (!unit.empty()) {
    const size_t power = units.find(unit);
    if (unit.size() != 1 || power == std::string::npos)
      throw Failure("--memory: '" + text + "' has an unknown unit; use K, M, G or T", 2);
    bytes = std::ldexp(number, 10 * int(power + 1));
  }
  if (bytes < 1 || bytes > 0x1p62) throw Failure("--memory: '" + text + "' is out of range", 2);
  return static_cast<unsigned long long>(bytes);
}

}  // namespace isoform::cli
