// What `slice`, `boxes` and `stack` share: the colour options, lists of
// numbers on the command line ("5,5,5" or "5"), and the summary of a
// coloured mesh.
#pragma once

#include <string>
#include <vector>

#include <CLI/App.hpp>

#include "cli.h"
#include "report.h"

namespace isoform::cli {

struct ColourArgs {
  std::string map;     // "" = the command's default
  std::string range;   // "lo,hi" or "" (from the data)
  int levels = 256;
};

// Registers --map, --range and --levels on app.
void add_colour_options(CLI::App& app, ColourArgs& args, const std::string& default_map);

// The C options for args, starting from the command's defaults in out.
// Throws Failure for an unknown map or a malformed range.
void apply_colour_options(const ColourArgs& args, isoform_colour_options& out);

// "a,b,c" as n numbers; one number stands for all n. Throws Failure naming
// option when the text is not that.
std::vector<double> parse_numbers(const std::string& text, const std::string& option, size_t n);
std::vector<int> parse_integers(const std::string& text, const std::string& option, size_t n);

// The map's name as the command line spells it.
std::string map_name(int map);

// Counts of a coloured mesh and the file it went to.
Json coloured_mesh_json(const isoform_mesh* mesh, const std::string& path);

}  // namespace isoform::cli
