// Checks on output paths, made before any long work so that a bad path fails
// in a moment instead of after a contour of many seconds.
#pragma once

#include <string>
#include <vector>

namespace isoform::cli {

// The extension of path in lower case, with its dot (".ply"), or "".
std::string lower_extension(const std::string& path);

// Throws Failure when output cannot be written as asked: it is the input
// file itself (under any name: symlinks and hard links count), its extension
// is not one of `extensions` (lower case, with the dot), or its folder does
// not exist. Permissions are left to the library's write.
void check_output_path(const std::string& input, const std::string& output,
                       const std::vector<std::string>& extensions);

// Creates folder dir (and its parents) when missing; Failure if it cannot.
void make_output_folder(const std::string& dir);

}  // namespace isoform::cli
