// `isoform info FILE`: the grids of a volume file and their facts.
#include <iostream>
#include <memory>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.h"
#include "report.h"

namespace isoform::cli {
namespace {

struct InfoArgs {
  std::string path;
  bool json = false;
};

void run_info(const InfoArgs& args) {
  const VolumePtr volume = open_volume(args.path);
  std::vector<isoform_grid_info> infos;
  const int count = isoform_volume_grid_count(volume.get());
  for (int i = 0; i < count; ++i) infos.push_back(grid_info(volume.get(), i));
  if (args.json) {
    Json grids = Json::array();
    for (const isoform_grid_info& info : infos) grids.push_back(grid_json(info));
    print_json({{"file", args.path}, {"grids", grids}});
    return;
  }
  std::cout << args.path << ": " << count << (count == 1 ? " grid" : " grids") << '\n';
  for (int i = 0; i < count; ++i) print_grid(std::cout, i, infos[size_t(i)]);
}

}  // namespace

Command add_info_command(CLI::App& parent) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* app = parent.add_subcommand(
      "info", "List the grids of a volume file and their facts");
  app->footer(
      "For each grid: name, value type, class (level set, fog volume, other), value range, "
      "background, active voxels, index bounding box, voxel size and the index-to-world "
      "transform.");
  app->add_option("file", args->path, "Volume file")->required();
  app->add_flag("--json", args->json, "Print one JSON object instead of text");
  return {app, [args] { run_info(*args); }};
}

}  // namespace isoform::cli
