// What the opaque handles of isoform.h hold, and the one place where C++
// exceptions become an isoform_status. Shared by the C API sources in libcore
// and vdbio; not installed, not seen by callers.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "../isoform.h"
#include "../mesh.h"
#include "../volume.h"

struct isoform_volume {
  std::shared_ptr<isoform::VolumeFile> file;
  // Grids loaded so far, by index: loading happens once per grid.
  mutable std::mutex mutex;
  mutable std::map<int, std::shared_ptr<const isoform::ScalarGrid>> loaded;

  std::shared_ptr<const isoform::ScalarGrid> grid(int index) const;
};

struct isoform_mesh {
  isoform::Mesh mesh;
  // True when the normals were estimated from the points (none in the input).
  bool normals_estimated = false;
  // The quantity and robust range of the curvature colours, when computed.
  int curvature_color_by = 2;
  double curvature_color_range[2] = {0.0, 0.0};
  // The report of the last isoform_reduce (reduced false until then).
  bool reduced = false;
  isoform_reduce_stats reduce_stats{};
  std::vector<std::string> reduce_left_alone;  // manifold_parts_only: why, per part
};

namespace isoform::capi {

// Records msg as this thread's last error and returns status.
isoform_status fail(isoform_status status, const std::string& msg);
// Clears this thread's last error.
void clear_error();

// Runs body (which returns isoform_status) and turns every exception into a
// status and a message. The only place the C boundary catches.
template <class Body>
isoform_status guarded(Body&& body) noexcept;

}  // namespace isoform::capi

#include "guarded.inl"
