// The built-in sample volume: a 3-D Shepp-Logan style head phantom.
#pragma once

#include <memory>

#include "volume.h"

namespace isoform {

// n^3 samples over [-1, 1]^3 (voxel size 2 / (n - 1), centred at the
// origin), one fog grid "density" in [0, 1]: a skull shell of density 1.0,
// brain 0.2, two ventricles 0.0 and small lesions 0.3. Ellipsoid edges are
// smoothed over about one voxel so that contours are not stair-stepped.
// Throws InvalidArgument for n < 16 or n > 1024.
std::shared_ptr<VolumeFile> make_phantom(int n);

}  // namespace isoform
