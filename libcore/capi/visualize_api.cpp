// The C API's volume visualisation calls (Chapter 2): slices, boxes, stacks,
// the images they make, and the colours and edges of meshes.
#include <cmath>
#include <cstring>

#include "../errors.h"
#include "../topology.h"
#include "../visualize/boxes.h"
#include "../visualize/mesh_build.h"
#include "../visualize/slices.h"
#include "../visualize/stack.h"
#include "handles.h"

struct isoform_image {
  isoform::visualize::Image image;
};

using isoform::capi::fail;
using isoform::capi::guarded;
namespace vis = isoform::visualize;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The grid and its domain, after the checks every call shares.
struct Target {
  std::shared_ptr<const isoform::ScalarGrid> grid;
  vis::Domain domain;
};

Target resolve(const isoform_volume* volume, int grid, const char* call) {
  if (!volume) throw isoform::InvalidArgument(std::string(call) + ": NULL volume");
  const std::string source = volume->file->path().empty() ? "volume" : volume->file->path();
  if (grid < 0 || grid >= volume->file->grid_count())
    throw isoform::InvalidArgument(source + ": no grid " + std::to_string(grid) + " (" +
                                   std::to_string(volume->file->grid_count()) + " grids)");
  const isoform::GridFacts facts = volume->file->facts(grid);
  Target t;
  t.domain.what = source + ", grid '" + facts.name + "'";
  if (!facts.is_scalar) throw isoform::Unsupported(t.domain.what + ": not a scalar grid (" + facts.value_type + ")");
  for (int a = 0; a < 3; ++a)
    if (facts.bbox_max[a] < facts.bbox_min[a])
      throw isoform::InvalidArgument(t.domain.what + ": the grid has no active values, so no domain");
  t.grid = volume->grid(grid);
  t.domain.lo = facts.bbox_min;
  t.domain.hi = facts.bbox_max;
  t.domain.to_world = t.grid->index_to_world;
  return t;
}

// The colour options, checked here so that the message names the grid.
vis::ColourSettings colour_settings(const isoform_colour_options& o, const vis::Domain& d) {
  if (o.map < 0 || o.map > 2) throw isoform::InvalidArgument(d.what + ": unknown colour map " + std::to_string(o.map));
  vis::ColourSettings s;
  s.map = vis::MapId(o.map);
  s.levels = o.levels;
  s.fixed_range = o.fixed_range != 0;
  s.range_min = o.range_min;
  s.range_max = o.range_max;
  try {
    vis::make_scale(s, {});
  } catch (const isoform::InvalidArgument& e) {
    throw isoform::InvalidArgument(d.what + ": " + e.what());
  }
  return s;
}

vis::SliceSettings slice_settings(const isoform_slice_options& o) {
  vis::SliceSettings s;
  for (int a = 0; a < 3; ++a) s.position[a] = o.position[a];
  s.world = o.world != 0;
  s.resolution = o.resolution;
  return s;
}

// Neighbours and statistics for isoform_mesh_stats_get and copy-out; parts
// stay as the maker set them.
isoform_mesh* wrap(isoform::Mesh mesh) {
  auto out = std::make_unique<isoform_mesh>();
  out->mesh = std::move(mesh);
  isoform::compute_neighbours(out->mesh);
  return out.release();
}

void check_axis(int axis, int highest, const vis::Domain& d) {
  if (axis < 0 || axis > highest)
    throw isoform::InvalidArgument(d.what + ": slice axis " + std::to_string(axis) + " is not 0.." +
                                   std::to_string(highest));
}

}  // namespace

extern "C" {

void isoform_colour_options_default(isoform_colour_options* o) {
  if (!o) return;
  o->map = ISOFORM_MAP_VIRIDIS;
  o->levels = 256;
  o->fixed_range = 0;
  o->range_min = 0.0;
  o->range_max = 1.0;
}

void isoform_slice_options_default(isoform_slice_options* o) {
  if (!o) return;
  for (int a = 0; a < 3; ++a) o->position[a] = 0.5;
  o->world = 0;
  o->resolution = 256;
  o->colour_bar = 1;
  o->height = 0.25;
  isoform_colour_options_default(&o->colour);
}

void isoform_boxes_options_default(isoform_boxes_options* o) {
  if (!o) return;
  for (int a = 0; a < 3; ++a) {
    o->q[a] = 5;
    o->gap[a] = 1.0;
    o->uvw_min[a] = 0.0;
    o->centre[a] = 0.0;
  }
  o->uvw_max[0] = 1.0;
  o->uvw_max[1] = kPi;
  o->uvw_max[2] = 1.5 * kPi;
  o->face_cells[0] = o->face_cells[1] = 1;
  o->centroid_lines = 0;
  o->domain = ISOFORM_DOMAIN_BOX;
  isoform_colour_options_default(&o->colour);
  o->colour.map = ISOFORM_MAP_GREEN_WHITE;
}

void isoform_stack_options_default(isoform_stack_options* o) {
  if (!o) return;
  for (int a = 0; a < 3; ++a) {
    o->n[a] = 8;
    o->view[a] = -1.0;
  }
  o->transparency = 0.5;
  isoform_colour_options_default(&o->colour);
}

isoform_status isoform_slice_image(const isoform_volume* volume, int grid, int axis,
                                   const isoform_slice_options* options, isoform_image** out) {
  return guarded([&] {
    if (!options || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_slice_image: NULL argument");
    *out = nullptr;
    const Target t = resolve(volume, grid, "isoform_slice_image");
    check_axis(axis, 2, t.domain);
    const auto slices = vis::sample_slices(*t.grid, t.domain, slice_settings(*options));
    const vis::ColourScale scale = vis::slices_scale(slices, colour_settings(options->colour, t.domain));
    auto image = std::make_unique<isoform_image>();
    image->image = vis::slice_image(slices[axis], scale, options->colour_bar != 0);
    *out = image.release();
    return ISOFORM_OK;
  });
}

isoform_status isoform_slice_mesh(const isoform_volume* volume, int grid, int axis, int kind,
                                  const isoform_slice_options* options, isoform_mesh** out) {
  return guarded([&] {
    if (!options || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_slice_mesh: NULL argument");
    *out = nullptr;
    const Target t = resolve(volume, grid, "isoform_slice_mesh");
    check_axis(axis, 3, t.domain);
    if (kind < 0 || kind > 2) return fail(ISOFORM_ERR_INVALID_ARGUMENT, t.domain.what + ": unknown slice kind " + std::to_string(kind));
    if (!(options->height >= 0.0) || !std::isfinite(options->height))
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, t.domain.what + ": graph height must be 0 or more");
    const auto slices = vis::sample_slices(*t.grid, t.domain, slice_settings(*options));
    const vis::ColourScale scale = vis::slices_scale(slices, colour_settings(options->colour, t.domain));
    isoform::Mesh mesh;
    for (int a = 0; a < 3; ++a)
      if (axis == 3 || axis == a)
        vis::append_mesh(mesh, vis::slice_mesh(slices[a], t.domain, scale, vis::SliceKind(kind), options->height));
    if (kind == ISOFORM_SLICE_PLANE) vis::append_mesh(mesh, vis::domain_outline(t.domain));
    *out = wrap(std::move(mesh));
    return ISOFORM_OK;
  });
}

isoform_status isoform_boxes(const isoform_volume* volume, int grid, const isoform_boxes_options* options,
                             isoform_mesh** out) {
  return guarded([&] {
    if (!options || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_boxes: NULL argument");
    *out = nullptr;
    const Target t = resolve(volume, grid, "isoform_boxes");
    vis::BoxSettings s;
    for (int a = 0; a < 3; ++a) {
      s.q[a] = options->q[a];
      s.gap[a] = options->gap[a];
    }
    s.face_cells = {options->face_cells[0], options->face_cells[1]};
    s.centroid_lines = options->centroid_lines != 0;
    vis::ParameterMap map;
    if (options->domain == ISOFORM_DOMAIN_BOX) {
      map = vis::box_map(t.domain);
    } else if (options->domain == ISOFORM_DOMAIN_SPHERICAL) {
      const isoform::Vec3d lo{options->uvw_min[0], options->uvw_min[1], options->uvw_min[2]};
      const isoform::Vec3d hi{options->uvw_max[0], options->uvw_max[1], options->uvw_max[2]};
      for (int a = 0; a < 3; ++a)
        if (!(hi[a] > lo[a])) return fail(ISOFORM_ERR_INVALID_ARGUMENT, t.domain.what + ": empty uvw range");
      map = vis::spherical_map(t.domain, lo, hi, {options->centre[0], options->centre[1], options->centre[2]});
    } else {
      return fail(ISOFORM_ERR_INVALID_ARGUMENT, t.domain.what + ": unknown domain kind " + std::to_string(options->domain));
    }
    *out = wrap(vis::domain_boxes(*t.grid, t.domain, map, s, colour_settings(options->colour, t.domain)));
    return ISOFORM_OK;
  });
}

isoform_status isoform_stack(const isoform_volume* volume, int grid, const isoform_stack_options* options,
                             isoform_mesh** out) {
  return guarded([&] {
    if (!options || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_stack: NULL argument");
    *out = nullptr;
    const Target t = resolve(volume, grid, "isoform_stack");
    vis::StackSettings s;
    for (int a = 0; a < 3; ++a) {
      s.n[a] = options->n[a];
      s.view[a] = options->view[a];
    }
    s.transparency = options->transparency;
    *out = wrap(vis::transparency_stack(*t.grid, t.domain, s, colour_settings(options->colour, t.domain)));
    return ISOFORM_OK;
  });
}

size_t isoform_mesh_color_count(const isoform_mesh* mesh) { return mesh ? mesh->mesh.colors.size() / 4 : 0; }

isoform_status isoform_mesh_copy_colors(const isoform_mesh* mesh, uint8_t* out) {
  return guarded([&] {
    if (!mesh || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_copy_colors: NULL argument");
    if (!mesh->mesh.colors.empty()) std::memcpy(out, mesh->mesh.colors.data(), mesh->mesh.colors.size());
    return ISOFORM_OK;
  });
}

size_t isoform_mesh_edge_count(const isoform_mesh* mesh) { return mesh ? mesh->mesh.edge_count() : 0; }

isoform_status isoform_mesh_copy_edges(const isoform_mesh* mesh, int32_t* out) {
  return guarded([&] {
    if (!mesh || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_mesh_copy_edges: NULL argument");
    if (!mesh->mesh.edges.empty())
      std::memcpy(out, mesh->mesh.edges.data(), mesh->mesh.edges.size() * sizeof(int32_t));
    return ISOFORM_OK;
  });
}

int isoform_image_width(const isoform_image* image) { return image ? image->image.width : 0; }
int isoform_image_height(const isoform_image* image) { return image ? image->image.height : 0; }

isoform_status isoform_image_range(const isoform_image* image, double* f_min, double* f_max) {
  return guarded([&] {
    if (!image || !f_min || !f_max) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_image_range: NULL argument");
    *f_min = image->image.f_min;
    *f_max = image->image.f_max;
    return ISOFORM_OK;
  });
}

isoform_status isoform_image_copy_rgba(const isoform_image* image, uint8_t* out) {
  return guarded([&] {
    if (!image || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_image_copy_rgba: NULL argument");
    std::memcpy(out, image->image.rgba.data(), image->image.rgba.size());
    return ISOFORM_OK;
  });
}

isoform_status isoform_image_copy_values(const isoform_image* image, float* out) {
  return guarded([&] {
    if (!image || !out) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_image_copy_values: NULL argument");
    std::memcpy(out, image->image.values.data(), image->image.values.size() * sizeof(float));
    return ISOFORM_OK;
  });
}

isoform_status isoform_image_save_png(const isoform_image* image, const char* path) {
  return guarded([&] {
    if (!image || !path) return fail(ISOFORM_ERR_INVALID_ARGUMENT, "isoform_image_save_png: NULL argument");
    vis::save_png(image->image, path);
    return ISOFORM_OK;
  });
}

void isoform_image_free(isoform_image* image) { delete image; }

}  // extern "C"
