// The C API's contour call.
#include "../contour/contour.h"
#include "../errors.h"
#include "handles.h"

using isoform::capi::fail;
using isoform::capi::guarded;

extern "C" {

void isoform_contour_options_default(isoform_contour_options* options) {
  if (!options) return;
  options->isovalue = 0.0;
  options->auto_isovalue = 1;
  options->method = ISOFORM_METHOD_CELLS;
  options->orientation = ISOFORM_ORIENT_AUTO;
  options->threads = 0;
}

isoform_status isoform_contour(const isoform_volume* volume, int grid, const isoform_contour_options* options,
                               isoform_progress* progress, isoform_mesh** out) {
  return guarded([&] {
    if (!volume || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_contour: NULL argument");
    *out = nullptr;
    isoform_contour_options defaults;
    isoform_contour_options_default(&defaults);
    const isoform_contour_options& o = options ? *options : defaults;
    if (o.method != ISOFORM_METHOD_CELLS && o.method != ISOFORM_METHOD_TETRA)
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_contour: unknown method " + std::to_string(o.method));
    if (o.orientation < ISOFORM_ORIENT_AUTO || o.orientation > ISOFORM_ORIENT_DECREASING)
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_contour: unknown orientation");
    if (grid < 0 || grid >= volume->file->grid_count())
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_contour: grid index " + std::to_string(grid) + " out of range");
    const isoform::Progress sink(progress);
    sink.stage(ISOFORM_STAGE_LOAD);
    const auto g = volume->grid(grid);
    isoform::ContourOptions co;
    co.isovalue = o.isovalue;
    co.auto_isovalue = o.auto_isovalue != 0;
    co.method = isoform::ContourMethod(o.method);
    co.orientation = isoform::Orientation(o.orientation);
    co.threads = o.threads;
    auto mesh = std::make_unique<isoform_mesh>();
    mesh->mesh = isoform::contour(*g, co, sink);
    *out = mesh.release();
    return ISOFORM_OK;
  });
}

}  // extern "C"
