// NIfTI-1 and NIfTI-2 scans (.nii, .nii.gz, and .hdr with its .img) read
// into libcore's DenseVolume, by isoform's own reader: every size in the
// header is checked against the file before anything is allocated for it,
// gzip data are decoded no further than the header promises, and nothing is
// printed (the reference library, niftilib, allocates from the header's
// dimensions and reports errors on stderr).
#pragma once

#include <memory>
#include <string>

#include "libcore/volume.h"

namespace isoform::vdbio {

// True if the name ends in .nii, .nii.gz, .hdr or .hdr.gz (any case).
bool has_nifti_name(const std::string& path);

// True if the file begins with a NIfTI-1 or NIfTI-2 header (uncompressed);
// throws IoError if it is missing or unreadable.
bool has_nifti_magic(const std::string& path);

// Reads one 3-D volume as the grid "density" (class fog). `volume` picks the
// 0-based volume of a 4-D file; -1 reads 3-D files and refuses a 4-D one
// with a message naming the choice. The index-to-world map is the sform
// when its code is set, else the qform (quaternion), else the voxel sizes
// alone; both codes name NIfTI's RAS frame, the units come from
// xyzt_units. scl_slope and scl_inter are applied (a slope of 0, or not
// finite, means none, as the format says). Throws FormatError for a damaged
// or lying header, Unsupported for complex or colour samples and 5-D data,
// InvalidArgument for a volume out of range.
std::shared_ptr<DenseVolume> read_nifti(const std::string& path, int volume);

}  // namespace isoform::vdbio
