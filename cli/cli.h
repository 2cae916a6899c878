// What the isoform commands share: the failure type that main() turns into an
// exit code, owning wrappers for the C API's handles, and the registration
// function of each subcommand. The CLI sees the library only through
// isoform.h (ARCHITECTURE.md: cli/ must not reach into libcore's C++ types).
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include <CLI/App.hpp>
#include <CLI/Validators.hpp>

#include "isoform.h"

namespace isoform::cli {

// A failure the user sees as one line, "isoform: error: <message>", and as
// the process's exit code (1 for every failure but an interrupt).
class Failure : public std::runtime_error {
 public:
  explicit Failure(const std::string& message, int exit_code = 1)
      : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

// The conventional exit code of a process stopped by Ctrl-C (128 + SIGINT).
constexpr int kInterruptedExitCode = 130;

// Throws Failure with isoform_last_error() when status is not ISOFORM_OK.
// Call it on the thread that made the failed call: the message is per thread.
void check(isoform_status status);

struct VolumeDeleter {
  void operator()(isoform_volume* volume) const { isoform_volume_free(volume); }
};
struct MeshDeleter {
  void operator()(isoform_mesh* mesh) const { isoform_mesh_free(mesh); }
};
using VolumePtr = std::unique_ptr<isoform_volume, VolumeDeleter>;
using MeshPtr = std::unique_ptr<isoform_mesh, MeshDeleter>;

// Thin throwing forms of the C API calls that several commands make.
VolumePtr open_volume(const std::string& path);
// The volume of a 4-D file that open_volume reads (--volume); -1, the
// default, refuses 4-D files.
void set_volume_index(int index);
isoform_grid_info grid_info(const isoform_volume* volume, int index);
// The index of grid `name` ("" = the first scalar grid).
int find_grid(const isoform_volume* volume, const std::string& name);
isoform_mesh_stats mesh_stats(const isoform_mesh* mesh);

// A check of an option's text: a finite number, 0 or more; its message
// quotes the text ("'abc' is not a number", "'-1' is negative ...").
CLI::Validator non_negative_number();

// "512M", "2G", "1.5T", "65536": bytes, with binary units (K = 1024).
// Throws Failure (usage exit code) on anything else.
unsigned long long parse_byte_size(const std::string& text);

// A subcommand and what runs it once its arguments are parsed. run throws
// Failure (or another std::exception) on error.
struct Command {
  CLI::App* app;
  std::function<void()> run;
};

Command add_info_command(CLI::App& parent);
Command add_contour_command(CLI::App& parent);
Command add_convert_command(CLI::App& parent);
Command add_pipeline_command(CLI::App& parent);
Command add_curvature_command(CLI::App& parent);
Command add_slice_command(CLI::App& parent);
Command add_boxes_command(CLI::App& parent);
Command add_stack_command(CLI::App& parent);
Command add_curvature_volume_command(CLI::App& parent);
Command add_compare_command(CLI::App& parent);
Command add_reduce_command(CLI::App& parent);
Command add_patch_command(CLI::App& parent);

}  // namespace isoform::cli
