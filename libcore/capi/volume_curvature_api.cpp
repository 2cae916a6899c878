// The C API's curvature of trivariate graphs (Section 4.3): a volume in, a
// volume of five result grids out.
#include "../curvature/graph_volume.h"
#include "../errors.h"
#include "handles.h"

using isoform::capi::fail;
using isoform::capi::guarded;

static_assert(int(isoform::GraphFit::JetCentred) == ISOFORM_GRAPH_FIT_JET_CENTRED &&
                  int(isoform::GraphFit::PlateletPartial) == ISOFORM_GRAPH_FIT_PLATELET_PARTIAL &&
                  int(isoform::GraphFit::None) == ISOFORM_GRAPH_FIT_NONE &&
                  isoform::kGraphFitCount == ISOFORM_GRAPH_FIT_COUNT,
              "GraphFit follows isoform_graph_fit");
static_assert(int(isoform::GraphMethod::Seed) == ISOFORM_VOLUME_CURVATURE_SEED, "GraphMethod follows the C enum");

namespace {

std::string source_name(const isoform_volume* v) {
  const std::string p = v->file->path();
  return p.empty() ? std::string("volume") : p;
}

isoform::GraphVolumeOptions options_of(const isoform_volume_curvature_options* options) {
  isoform_volume_curvature_options o;
  isoform_volume_curvature_options_default(&o);
  if (options) o = *options;
  if (o.method != ISOFORM_VOLUME_CURVATURE_DEFAULT && o.method != ISOFORM_VOLUME_CURVATURE_SEED)
    throw isoform::InvalidArgument("isoform_volume_curvature: unknown method " + std::to_string(o.method));
  if (o.threads < 0) throw isoform::InvalidArgument("isoform_volume_curvature: threads must be 0 or more");
  isoform::GraphVolumeOptions out;
  out.method = isoform::GraphMethod(o.method);
  out.threads = o.threads;
  return out;
}

void copy_summary(const isoform::GraphSummary& s, isoform_curvature_summary& out) {
  out.min = s.min;
  out.max = s.max;
  out.mean = s.mean;
  out.p01 = s.p01;
  out.p05 = s.p05;
  out.p25 = s.p25;
  out.p50 = s.p50;
  out.p75 = s.p75;
  out.p95 = s.p95;
  out.p99 = s.p99;
}

}  // namespace

extern "C" {

void isoform_volume_curvature_options_default(isoform_volume_curvature_options* options) {
  if (!options) return;
  options->method = ISOFORM_VOLUME_CURVATURE_DEFAULT;
  options->threads = 0;
}

isoform_status isoform_volume_curvature(const isoform_volume* volume, int grid,
                                        const isoform_volume_curvature_options* options,
                                        isoform_progress* progress, isoform_volume** out) {
  return guarded([&] {
    if (!volume || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_volume_curvature: NULL argument");
    *out = nullptr;
    const isoform::GraphVolumeOptions o = options_of(options);
    if (grid < 0 || grid >= volume->file->grid_count())
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, source_name(volume) + ": grid index " + std::to_string(grid) +
                                                    " out of range (" +
                                                    std::to_string(volume->file->grid_count()) + " grids)");
    const isoform::Progress sink(progress);
    sink.stage(ISOFORM_STAGE_LOAD);
    const auto scalar = volume->grid(grid);  // throws Unsupported for vector grids
    sink.stage(ISOFORM_STAGE_CURVATURE);     // the fits' fraction is over bricks
    auto result = isoform::graph_curvature_volume(*scalar, volume->file->path(), o, sink);
    sink.stage(ISOFORM_STAGE_DONE);
    auto handle = std::make_unique<isoform_volume>();
    handle->file = std::move(result);
    *out = handle.release();
    return ISOFORM_OK;
  });
}

isoform_status isoform_volume_curvature_stats_get(const isoform_volume* result,
                                                  isoform_volume_curvature_stats* out) {
  return guarded([&] {
    if (!result || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_volume_curvature_stats_get: NULL argument");
    const auto* curvature = dynamic_cast<const isoform::GraphCurvatureVolume*>(result->file.get());
    if (!curvature)
      return fail(ISOFORM_ERR_INVALID_ARGUMENT,
                  source_name(result) + ": not a curvature result (made by isoform_volume_curvature)");
    const isoform::GraphCurvatureStats& s = curvature->stats();
    *out = isoform_volume_curvature_stats{};
    out->method = int(s.method);
    out->points = s.points;
    for (int f = 0; f < ISOFORM_GRAPH_FIT_COUNT; ++f) out->fits[f] = s.fits[size_t(f)];
    for (int g = 0; g < isoform::kGraphGrids; ++g) copy_summary(s.summary[size_t(g)], out->grids[g]);
    return ISOFORM_OK;
  });
}

const char* isoform_graph_fit_name(int fit) {
  switch (fit) {
    case ISOFORM_GRAPH_FIT_JET_CENTRED: return "degree-6 fit on the centred 7x7x7 box";
    case ISOFORM_GRAPH_FIT_JET_SHIFTED: return "degree-6 fit, box moved or cut at the data's edge";
    case ISOFORM_GRAPH_FIT_JET_REDUCED: return "degree-2 fit, box with inactive voxels";
    case ISOFORM_GRAPH_FIT_PLATELET: return "seed's platelet fit";
    case ISOFORM_GRAPH_FIT_PLATELET_PARTIAL: return "seed's fit on a one-sided platelet";
    case ISOFORM_GRAPH_FIT_NONE: return "no fit (too few active neighbours; results 0)";
    default: return "unknown";
  }
}

}  // extern "C"
