// Dropping a mesh's small parts (--min-part, --largest), which `contour`
// and `reduce` share: the options as the user writes them, the call, the
// summary of what was dropped.
#pragma once

#include <ostream>
#include <string>

#include "cli.h"
#include "report.h"

namespace CLI {
class App;
}

namespace isoform::cli {

struct PartSettings {
  std::string min_part;   // "" (off), "50" (triangles), "1mm3", "0.5ml", "2u3" (world units cubed)
  long long largest = 0;  // keep the K largest parts; 0 keeps all
  bool wanted() const { return !min_part.empty() || largest > 0; }
};

void add_part_options(CLI::App& app, PartSettings& settings);

// The filter the options ask for; `unit` is the input's world unit ("mm",
// "m", "um", or "" when unknown), which a volume in mm3, ml, ... needs.
// Failure (exit 2) naming the option for a bad value; `input` is named when
// a volume needs a unit the input does not state.
isoform_part_filter part_filter(const PartSettings& settings, const std::string& unit, const std::string& input);

// Drops the parts; the stats say what went.
isoform_part_filter_stats drop_parts(isoform_mesh* mesh, const isoform_part_filter& filter);

Json parts_json(const isoform_part_filter_stats& stats);
void print_parts(std::ostream& out, const isoform_part_filter_stats& stats);

}  // namespace isoform::cli
