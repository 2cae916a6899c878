// Conversions between OpenVDB's grid vocabulary and libcore's: transforms,
// grid classes, value type names, and scalar trees converted to float.
#pragma once

#include <openvdb/openvdb.h>

#include <string>

#include "libcore/volume.h"

namespace isoform::vdbio {

// Fills OpenVDB's grid, metadata and map registries, once per process; every
// entry point that reads or writes a file calls it first.
void initialize_openvdb();

// OpenVDB's linear maps act on row vectors (world = (i, j, k, 1) * M, the
// translation in the last row); Affine acts on column vectors. Throws
// Unsupported naming `what` (file and grid) for non-affine maps (frustums).
Affine to_affine(const openvdb::math::Transform& transform, const std::string& what);
openvdb::math::Transform::Ptr to_transform(const Affine& affine);

GridClass to_grid_class(openvdb::GridClass grid_class);
openvdb::GridClass to_vdb_class(GridClass grid_class);

// "float", "half" (float saved as 16 bits), "double", "int32", "vec3s", ...
std::string value_type_name(const openvdb::GridBase& grid);

// True for the value types isoform contours: float, double, int32, int64.
bool is_scalar_grid(const openvdb::GridBase& grid);

// The grid's tree as floats, sharing it when it already is one; metadata,
// name, class and transform are kept. Requires is_scalar_grid(grid).
openvdb::FloatGrid::Ptr to_float_grid(const openvdb::GridBase::Ptr& grid);

}  // namespace isoform::vdbio
