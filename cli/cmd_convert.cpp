// `isoform convert IN -o OUT.vdb`: a dense scan (raw, NRRD) or a VDB file to
// a sparse OpenVDB file.
#include <array>
#include <iostream>
#include <memory>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.h"
#include "paths.h"
#include "report.h"

namespace isoform::cli {
namespace {

// In the order of isoform_scalar_type, which --help shows.
using ScalarTypes = std::vector<std::pair<std::string, isoform_scalar_type>>;
const ScalarTypes& scalar_types() {
  static const ScalarTypes types = {
      {"u8", ISOFORM_U8},   {"i8", ISOFORM_I8},   {"u16", ISOFORM_U16}, {"i16", ISOFORM_I16},
      {"u32", ISOFORM_U32}, {"i32", ISOFORM_I32}, {"f32", ISOFORM_F32}, {"f64", ISOFORM_F64}};
  return types;
}

// --type is checked against scalar_types() when parsed, so name is one of them.
isoform_scalar_type scalar_type(const std::string& name) {
  for (const auto& [entry_name, type] : scalar_types())
    if (entry_name == name) return type;
  return ISOFORM_U16;
}

// The name of a library scalar type; the library's default is one of them.
std::string type_name(int code) {
  for (const auto& [name, type] : scalar_types())
    if (type == code) return name;
  return "u16";
}

struct ConvertArgs {
  std::string input;
  std::string output;
  // Raw layout; defaults are filled from isoform_raw_options_default.
  std::array<int, 3> dims{0, 0, 0};
  std::string type;
  std::string endian;
  std::array<double, 3> spacing{};
  std::array<double, 3> origin{};
  size_t header_bytes = 0;
  CLI::Option* dims_option = nullptr;  // set once --dims is registered
  bool json = false;
};

void set_raw_defaults(ConvertArgs& args) {
  isoform_raw_options defaults;
  isoform_raw_options_default(&defaults);
  args.type = type_name(defaults.scalar_type);
  args.endian = defaults.big_endian ? "big" : "little";
  for (int axis = 0; axis < 3; ++axis) {
    args.spacing[size_t(axis)] = defaults.spacing[axis];
    args.origin[size_t(axis)] = defaults.origin[axis];
  }
  args.header_bytes = defaults.header_bytes;
}

VolumePtr open_raw(const ConvertArgs& args) {
  isoform_raw_options options;
  isoform_raw_options_default(&options);
  for (int axis = 0; axis < 3; ++axis) {
    options.dims[axis] = args.dims[size_t(axis)];
    options.spacing[axis] = args.spacing[size_t(axis)];
    options.origin[axis] = args.origin[size_t(axis)];
  }
  options.scalar_type = scalar_type(args.type);
  options.big_endian = args.endian == "big" ? 1 : 0;
  options.header_bytes = args.header_bytes;
  isoform_volume* volume = nullptr;
  check(isoform_volume_open_raw(args.input.c_str(), &options, &volume));
  return VolumePtr(volume);
}

// A file is read as raw when --dims says how, or when it is a .raw file,
// which has no header to say it: then --dims is required.
VolumePtr open_input(const ConvertArgs& args) {
  if (args.dims_option->count() > 0) return open_raw(args);
  if (lower_extension(args.input) == ".raw")
    throw Failure(args.input + ": a .raw file has no header; give its size with --dims X,Y,Z "
                               "(and --type, --spacing as needed)");
  return open_volume(args.input);
}

void report_convert(const ConvertArgs& args, const isoform_volume* volume) {
  const int count = isoform_volume_grid_count(volume);
  if (args.json) {
    Json grids = Json::array();
    for (int i = 0; i < count; ++i) grids.push_back(grid_json(grid_info(volume, i)));
    print_json({{"input", args.input}, {"output", args.output}, {"grids", grids}});
    return;
  }
  for (int i = 0; i < count; ++i) print_grid(std::cout, i, grid_info(volume, i));
  std::cout << "wrote " << args.output << '\n';
}

void run_convert(const ConvertArgs& args) {
  check_output_path(args.input, args.output, {".vdb"});
  const VolumePtr volume = open_input(args);
  check(isoform_volume_save_vdb(volume.get(), args.output.c_str()));
  report_convert(args, volume.get());
}

void add_raw_options(CLI::App& app, ConvertArgs& args) {
  args.dims_option =
      app.add_option("--dims", args.dims, "Raw samples along x (fastest), y, z: X,Y,Z")
          ->delimiter(',');
  const auto raw_only = [&](CLI::Option* option) { option->needs(args.dims_option); };
  raw_only(app.add_option("--type", args.type, "Raw sample type")
               ->check(CLI::IsMember(scalar_types()))
               ->capture_default_str());
  raw_only(app.add_option("--endian", args.endian, "Raw byte order")
               ->check(CLI::IsMember({"little", "big"}))
               ->capture_default_str());
  raw_only(app.add_option("--spacing", args.spacing, "World units between samples: SX,SY,SZ")
               ->delimiter(',')
               ->capture_default_str());
  raw_only(app.add_option("--origin", args.origin, "World position of sample (0,0,0): OX,OY,OZ")
               ->delimiter(',')
               ->capture_default_str());
  raw_only(app.add_option("--header-bytes", args.header_bytes, "Bytes to skip at the start")
               ->capture_default_str());
}

}  // namespace

Command add_convert_command(CLI::App& parent) {
  auto args = std::make_shared<ConvertArgs>();
  set_raw_defaults(*args);
  CLI::App* app = parent.add_subcommand(
      "convert", "Convert a dense scan (.raw, .nrrd, .nhdr, .nii, .nii.gz) or a .vdb into a sparse .vdb");
  app->footer(
      "A headerless .raw file needs --dims; the other raw options describe its layout. "
      "Example: isoform convert head.raw --dims 64,64,93 --type u16 --spacing 3.2,3.2,1.5 "
      "-o head.vdb");
  app->add_option("file", args->input, "Input volume: .raw (with --dims), .nrrd, .nhdr, .nii, .nii.gz, .vdb")
      ->required();
  app->add_option("-o,--output", args->output, "OpenVDB file to write (.vdb)")->required();
  add_raw_options(*app, *args);
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args] { run_convert(*args); }};
}

}  // namespace isoform::cli
