// What every fuzz target shares: the input bytes as a file the C API can
// open (readers take paths, and some choose their format by the file's
// extension), and the C API's calls on what a reader accepted, each bounded
// so that one input stays well under the fuzzers' time and memory limits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "isoform.h"

namespace isoform::fuzz {

// Writes the bytes to a file of this process with the given extension
// (".vdb", ".ply", ...) in /dev/shm (or the temporary folder) and returns
// its path; the same path each call, so nothing accumulates.
std::string as_file(const uint8_t* data, size_t size, const char* extension);

// Describes every grid, and contours each scalar grid of at most 2^16
// active voxels on one thread, freeing all it made.
void exercise_volume(isoform_volume* volume);

// Curvature, the parts of one triangle (or of almost no volume) dropped, a
// reduction to half and a level-2 side-vertex surface of a mesh of at most
// 4,096 triangles, each on what the step before left.
void exercise_mesh(isoform_mesh* mesh);

// One fuzz input as a volume file (isoform_volume_open_with; options NULL
// for the defaults) or a mesh file (isoform_mesh_load) of the given
// extension, exercised as above when the reader accepts it.
void fuzz_volume_file(const uint8_t* data, size_t size, const char* extension,
                      const isoform_open_options* options = nullptr);
void fuzz_mesh_file(const uint8_t* data, size_t size, const char* extension);

}  // namespace isoform::fuzz
