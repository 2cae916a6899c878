// The C API's comparison calls: the side-vertex surface against the Loop
// limit surface and the flat triangles, measured over the same mesh, the
// report and its files.
#include <cstring>

#include "../compare/compare.h"
#include "../compare/linear_surface.h"
#include "../compare/loop_surface.h"
#include "../compare/report_files.h"
#include "../errors.h"
#include "../patch/side_vertex_surface.h"
#include "../progress.h"
#include "../topology.h"
#include "handles.h"

using isoform::capi::fail;
using isoform::capi::guarded;
namespace cmp = isoform::compare;

struct isoform_compare_report {
  cmp::CompareResult result;
  cmp::StudyInfo info;
  std::string notes_text;  // the notes, one per line, made once
};

namespace {

cmp::CompareSettings settings_of(const isoform_compare_options& o) {
  cmp::CompareSettings s;
  s.level = o.level;
  s.table_triangles = o.table_triangles;
  if (o.level < 1 || o.level > 64)
    throw isoform::InvalidArgument("isoform_compare: level " + std::to_string(o.level) + " is not 1..64");
  if (o.table_triangles < 0) throw isoform::InvalidArgument("isoform_compare: table_triangles must not be negative");
  return s;
}

std::string loop_text(const cmp::LoopOptions& o) {
  return "isolation " + std::to_string(o.isolation) + ", Gregory end caps, boundary " +
         (o.sharp_corners ? "edges and corners interpolated" : "edges interpolated, corners smoothed");
}

// The reference the options ask for (null for none), placed over the mesh.
std::unique_ptr<cmp::Reference> make_reference(const isoform::Mesh& mesh, const isoform_volume* volume,
                                               const isoform_compare_options& o) {
  const int kind = volume ? ISOFORM_REFERENCE_VOLUME : o.reference;
  isoform::Vec3d c{o.centre[0], o.centre[1], o.centre[2]};
  double major = o.radius, minor = o.minor_radius;
  switch (kind) {
    case ISOFORM_REFERENCE_NONE:
      return nullptr;
    case ISOFORM_REFERENCE_SPHERE:
      if (o.fit_reference) cmp::fit_sphere(mesh, c, major);
      return cmp::make_sphere_reference(c, major);
    case ISOFORM_REFERENCE_TORUS:
      if (o.fit_reference) cmp::fit_torus(mesh, c, major, minor);
      return cmp::make_torus_reference(c, major, minor);
    case ISOFORM_REFERENCE_VOLUME:
      break;
    default:
      throw isoform::InvalidArgument("isoform_compare: unknown reference kind " + std::to_string(kind));
  }
  if (!volume) throw isoform::InvalidArgument("isoform_compare: a volume reference needs a volume");
  const std::string source = volume->file->path().empty() ? "volume" : volume->file->path();
  int grid = o.grid;
  if (grid < 0)
    for (int i = 0; i < volume->file->grid_count() && grid < 0; ++i)
      if (volume->file->facts(i).is_scalar) grid = i;
  if (grid < 0 || grid >= volume->file->grid_count())
    throw isoform::InvalidArgument(source + ": no scalar grid to compare with");
  const isoform::GridFacts facts = volume->file->facts(grid);
  if (!facts.is_scalar) throw isoform::Unsupported(source + ", grid '" + facts.name + "': not a scalar grid");
  return cmp::make_volume_reference(*volume->grid(grid), o.isovalue, mesh, source + ", grid '" + facts.name + "'");
}

isoform_compare_stats to_c(const cmp::Stats& s) { return {s.count, s.max, s.rms, s.mean}; }
isoform_compare_spread to_c(const cmp::Spread& s) { return {s.count, s.p05, s.p50, s.p95, s.mean, s.stddev}; }

}  // namespace

extern "C" {

void isoform_compare_options_default(isoform_compare_options* o) {
  if (!o) return;
  std::memset(o, 0, sizeof(*o));
  o->level = 8;
  o->reference = ISOFORM_REFERENCE_NONE;
  o->fit_reference = 1;
  o->radius = 1.0;
  o->minor_radius = 0.25;
  o->grid = -1;
  o->loop_isolation = 6;
  o->loop_sharp_corners = 1;
  o->table_triangles = 2000;
  o->side_vertex = 1;
}

isoform_status isoform_compare(const isoform_mesh* mesh, const isoform_volume* volume,
                               const isoform_compare_options* options, isoform_progress* progress,
                               isoform_compare_report** out) {
  return guarded([&] {
    if (!mesh || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_compare: NULL argument");
    *out = nullptr;
    isoform_compare_options o;
    isoform_compare_options_default(&o);
    if (options) o = *options;
    const cmp::CompareSettings settings = settings_of(o);
    const isoform::Progress p(progress);
    p.stage(ISOFORM_STAGE_COMPARE);
    const isoform::Mesh& base = mesh->mesh;
    const std::string what = o.input_name ? o.input_name : "mesh";
    if (base.triangle_count() == 0) throw isoform::InvalidArgument(what + ": the mesh has no triangles");
    isoform::Mesh topo;  // neighbours for the edge measures, if the mesh lacks them
    const isoform::Mesh* m = &base;
    if (base.neighbours.size() != base.triangles.size()) {
      topo = base;
      isoform::compute_neighbours(topo);
      m = &topo;
    }
    cmp::LoopOptions loop_options;
    loop_options.isolation = o.loop_isolation;
    loop_options.sharp_corners = o.loop_sharp_corners != 0;
    std::string error;
    auto loop = cmp::make_loop_surface(*m, loop_options, error);
    if (!loop) throw isoform::InvalidArgument(what + ": no Loop surface: " + error);
    auto linear = cmp::make_linear_surface(*m);
    const auto reference = make_reference(*m, volume, o);
    auto report = std::make_unique<isoform_compare_report>();
    report->info.input = o.input_name ? o.input_name : "";
    report->info.loop_options = loop_text(loop_options);
    std::vector<cmp::NamedSurface> surfaces = {{"linear", linear.get()}, {"loop", loop.get()}};
    std::unique_ptr<isoform::TriangleSurface> side_vertex;
    std::string note;
    if (o.side_vertex) {
      side_vertex = isoform::patch::make_side_vertex_surface(*m, isoform::patch::PatchOptions{}, error);
      if (side_vertex) surfaces.push_back({"side-vertex", side_vertex.get()});
      else note = "side-vertex surface left out: " + error;
    }
    report->result = cmp::compare_surfaces(*m, surfaces, reference.get(), settings, p);
    if (!note.empty()) report->result.notes.push_back(note);
    for (const std::string& n : report->result.notes) report->notes_text += n + "\n";
    p.stage(ISOFORM_STAGE_DONE);
    *out = report.release();
    return ISOFORM_OK;
  });
}

int isoform_compare_report_surface_count(const isoform_compare_report* r) {
  return r ? int(r->result.surfaces.size()) : 0;
}

const char* isoform_compare_report_surface_name(const isoform_compare_report* r, int index) {
  if (!r || index < 0 || index >= int(r->result.surfaces.size())) return nullptr;
  return r->result.surfaces[size_t(index)].name.c_str();
}

isoform_status isoform_compare_report_metrics(const isoform_compare_report* r, int index,
                                              isoform_compare_metrics* out) {
  return guarded([&] {
    if (!r || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_compare_report_metrics: NULL argument");
    if (index < 0 || index >= int(r->result.surfaces.size()))
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_compare_report_metrics: no surface " + std::to_string(index));
    const cmp::SurfaceMetrics& m = r->result.surfaces[size_t(index)];
    out->samples = m.samples;
    out->failed_samples = m.failed_samples;
    out->deviation = to_c(m.deviation);
    out->data_point_error = to_c(m.data_point_error);
    out->normal_gap = to_c(m.normal_gap);
    out->position_gap = to_c(m.position_gap);
    out->mean_curvature_jump = to_c(m.mean_curvature_jump);
    out->mean_curvature_error = to_c(m.mean_curvature_error);
    out->mean_curvature = to_c(m.mean_curvature);
    out->gauss_curvature = to_c(m.gauss_curvature);
    out->evaluation_seconds = m.evaluation_seconds;
    out->seconds_per_million = m.seconds_per_million;
    out->tessellation_triangles = m.tessellation_triangles;
    return ISOFORM_OK;
  });
}

const char* isoform_compare_report_reference(const isoform_compare_report* r) {
  return r ? r->result.reference_description.c_str() : "";
}

const char* isoform_compare_report_deviation_unit(const isoform_compare_report* r) {
  return r ? r->result.deviation_unit.c_str() : "";
}

const char* isoform_compare_report_notes(const isoform_compare_report* r) {
  return r ? r->notes_text.c_str() : "";
}

isoform_status isoform_compare_report_tessellation(const isoform_compare_report* r, int index, isoform_mesh** out) {
  return guarded([&] {
    if (!r || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_compare_report_tessellation: NULL argument");
    *out = nullptr;
    if (index < 0 || index >= int(r->result.tessellations.size()))
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_compare_report_tessellation: no surface " + std::to_string(index));
    auto mesh = std::make_unique<isoform_mesh>();
    mesh->mesh = r->result.tessellations[size_t(index)];
    isoform::compute_topology(mesh->mesh);
    *out = mesh.release();
    return ISOFORM_OK;
  });
}

isoform_status isoform_compare_report_write(const isoform_compare_report* r, const char* directory) {
  return guarded([&] {
    if (!r || !directory) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_compare_report_write: NULL argument");
    cmp::write_report(r->result, r->info, directory);
    return ISOFORM_OK;
  });
}

void isoform_compare_report_free(isoform_compare_report* r) { delete r; }

}  // extern "C"
