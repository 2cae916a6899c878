// Checks of option values shared by the commands (see cli.h).
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

}  // namespace isoform::cli
