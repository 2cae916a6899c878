// The smooth-surface steps of `pipeline` (see surface_steps.h).
#include "surface_steps.h"

#include <memory>

#include <nlohmann/json.hpp>

#include "contouring.h"
#include "paths.h"

namespace isoform::cli {
namespace {

struct PatchDeleter {
  void operator()(isoform_patch* p) const { isoform_patch_free(p); }
};
struct ReportDeleter {
  void operator()(isoform_compare_report* r) const { isoform_compare_report_free(r); }
};

Json stats_json(const isoform_compare_stats& s) { return {{"max", s.max}, {"rms", s.rms}, {"count", s.count}}; }

}  // namespace

MeshPtr smooth_surface(const isoform_mesh* mesh, int level, const std::string& input,
                       const ProgressOptions& progress) {
  isoform_patch* raw = nullptr;
  if (isoform_patch_create(mesh, nullptr, &raw) != ISOFORM_OK)
    throw Failure(input + ": " + isoform_last_error());
  const std::unique_ptr<isoform_patch, PatchDeleter> patch(raw);
  isoform_mesh* out = nullptr;
  run_with_progress([&](isoform_progress* p) { return isoform_patch_tessellate(patch.get(), level, p, &out); },
                    progress);
  return MeshPtr(out);
}

Json compare_study(const isoform_mesh* mesh, const isoform_volume* volume, int grid, double isovalue,
                   int level, const std::string& input, const std::string& folder,
                   const ProgressOptions& progress) {
  isoform_compare_options o;
  isoform_compare_options_default(&o);
  o.level = level;
  o.grid = grid;
  o.isovalue = isovalue;
  o.input_name = input.c_str();
  isoform_compare_report* raw = nullptr;
  run_with_progress([&](isoform_progress* p) { return isoform_compare(mesh, volume, &o, p, &raw); }, progress);
  const std::unique_ptr<isoform_compare_report, ReportDeleter> report(raw);
  make_output_folder(folder);
  check(isoform_compare_report_write(report.get(), folder.c_str()));
  Json summary = Json::object();
  for (int i = 0; i < isoform_compare_report_surface_count(report.get()); ++i) {
    const std::string name = isoform_compare_report_surface_name(report.get(), i);
    isoform_mesh* t = nullptr;
    check(isoform_compare_report_tessellation(report.get(), i, &t));
    const MeshPtr tessellation(t);
    save_mesh(tessellation.get(), folder + "/surface-" + name + ".ply");
    isoform_compare_metrics m;
    check(isoform_compare_report_metrics(report.get(), i, &m));
    summary[name] = {{"deviation_voxels", stats_json(m.deviation)},
                     {"data_point_error", stats_json(m.data_point_error)},
                     {"normal_gap", stats_json(m.normal_gap)},
                     {"mean_curvature_jump", stats_json(m.mean_curvature_jump)}};
  }
  return summary;
}

}  // namespace isoform::cli
