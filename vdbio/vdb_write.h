// Writes a VolumeFile as an OpenVDB file.
#pragma once

#include <string>

#include "libcore/volume.h"

namespace isoform::vdbio {

// Every scalar grid becomes a FloatGrid with its name, class and transform.
// - Grids of an OpenVDB file (vdb_file.h) are written as they are stored:
//   scalar grids as float with their own topology and tiles, and
//   non-scalar grids (vectors, masks, points) copied unchanged, so a VDB
//   round trip loses nothing.
// - Other volumes (dense scans) are read brick by brick; samples equal to
//   the background are left inactive, so a scan with empty space becomes
//   sparse. Outside the array the written grid holds the background.
// The file is written beside path under a temporary name and renamed over
// path, so a failure leaves nothing behind. Throws InvalidArgument when path
// is the volume's own source file, IoError when the directory is missing or
// not writable.
void write_vdb(const VolumeFile& volume, const std::string& path);

}  // namespace isoform::vdbio
