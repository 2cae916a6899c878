// The built-in sample volume: a 3-D Shepp-Logan style head phantom.
#pragma once

#include <memory>

#include "volume.h"

namespace isoform {

// n^3 samples over [-1, 1]^3 (voxel size 2 / (n - 1), centred at the
// origin), one fog grid "density" in [0, 1]: a skull shell of density 1.0,
// brain 0.2, two ventricles 0.0 and small lesions 0.3. Each ellipsoid's
// density ramps over two voxels on each side of its boundary, linearly
// within one voxel, so that the 0.5 contour's linear crossings lie on the
// skull's ellipsoids (at about 115^3 and finer; the skull is 0.07 thick, and
// coarser grids ramp over a quarter of that to keep it).
// Throws InvalidArgument for n < 16 or n > 1024.
std::shared_ptr<VolumeFile> make_phantom(int n);

}  // namespace isoform
