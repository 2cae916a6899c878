// The isoform command: parses the command line, runs one subcommand, and is
// the one place that turns failures into messages and exit codes:
// 0 success, 1 failure (one line on stderr), 2 usage error, 130 interrupted.
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli.h"

namespace {

using isoform::cli::Command;

constexpr int kUsageExitCode = 2;

std::string version_text() {
  const int v = isoform_version();
  return "isoform " + std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." +
         std::to_string(v % 100);
}

// Library messages are meant to be one line; a stray newline would break the
// "one line on stderr" promise scripts rely on.
void print_error(std::string message) {
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  std::cerr << "isoform: error: " << message << '\n';
}

int run_parsed(const std::vector<Command>& commands) {
  for (const Command& command : commands) {
    if (!command.app->parsed()) continue;
    try {
      command.run();
      return 0;
    } catch (const isoform::cli::Failure& failure) {
      print_error(failure.what());
      return failure.exit_code();
    } catch (const std::exception& error) {
      print_error(error.what());
      return 1;
    }
  }
  return kUsageExitCode;  // require_subcommand(1) makes this unreachable
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"isoform: scalar volumes (OpenVDB grids, CT scans) to watertight triangle meshes "
               "(Chapter 3) and to slices, boxes and transparency stacks (Chapter 2), after Hamann "
               "(1991)",
               "isoform"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text);
  // Given before or after the subcommand: subcommands pass on what they do
  // not know to the app.
  app.fallthrough();
  std::string memory;
  app.add_option("--memory", memory,
                 "most memory an input file's data may take once read, such as 2G (default: half "
                 "the machine's memory); a file that needs more is refused before it is read");
  int volume = -1;
  app.add_option("--volume", volume,
                 "the volume K (from 0) of a 4-D NIfTI file to read; 4-D files are refused without it")
      ->check(CLI::NonNegativeNumber);
  const std::vector<Command> commands = {
      isoform::cli::add_info_command(app), isoform::cli::add_contour_command(app),
      isoform::cli::add_convert_command(app), isoform::cli::add_pipeline_command(app),
      isoform::cli::add_curvature_command(app),
      isoform::cli::add_slice_command(app),   isoform::cli::add_boxes_command(app),
      isoform::cli::add_stack_command(app),
      isoform::cli::add_curvature_volume_command(app),
      isoform::cli::add_compare_command(app),
      isoform::cli::add_reduce_command(app),
      isoform::cli::add_patch_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // app.exit prints help or version (code 0) or the usage error.
    return app.exit(error) == 0 ? 0 : kUsageExitCode;
  }
  isoform::cli::set_volume_index(volume);
  if (!memory.empty()) {
    try {
      isoform_set_memory_budget(isoform::cli::parse_byte_size(memory));
    } catch (const isoform::cli::Failure& failure) {
      print_error(failure.what());
      return failure.exit_code();
    }
  }
  return run_parsed(commands);
}
