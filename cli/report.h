// Summaries for people (aligned text on stdout) and for machines (--json),
// built from the C API's plain structs.
#pragma once

#include <ostream>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "isoform.h"

namespace isoform::cli {

// Keys stay in the order they are written, which reads better than sorted.
using Json = nlohmann::ordered_json;

// "level set", "fog volume" or "other".
std::string class_name(int grid_class);
// A number as a person reads it: shortest of fixed or exponent, 6 digits.
std::string format_number(double value);
// "RAS, unit mm", or "not stated" for what the file does not say.
std::string frame_text(const isoform_grid_info& info);
// Seconds with two decimals and the unit: "1.25 s".
std::string format_seconds(double seconds);

// One row of a text summary: a label padded to a common width, then value.
void print_row(std::ostream& out, const std::string& label, const std::string& value);

// Every field of isoform_grid_info; the value range is null for grids that
// are not scalar, and the transform is four rows of four.
Json grid_json(const isoform_grid_info& info);
void print_grid(std::ostream& out, int index, const isoform_grid_info& info);

// Every field of isoform_mesh_stats.
Json mesh_json(const isoform_mesh_stats& stats);
// The rows a person wants: counts, closedness, isovalue, Chapter 3 figures.
void print_mesh(std::ostream& out, const isoform_mesh_stats& stats);

// j on stdout, indented, with a final newline.
void print_json(const Json& j);

}  // namespace isoform::cli
