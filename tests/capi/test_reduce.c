/* The reduction (Chapter 5) through the C API: the options' defaults and
 * refusals, the stats, and real contours (cube.vdb, headsq at the bone
 * level 1150) reduced by 90 %: closed, manifold, same Euler characteristic
 * (genus) and parts.
 * Usage: test_capi_reduce CASE [SCRATCH_DIR] */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "isoform.h"

static const char* data_path(const char* name) {
  static char buf[1024];
  snprintf(buf, sizeof buf, "%s/%s", ISOFORM_SHARED_DATA, name);
  return buf;
}

static isoform_mesh* contour(isoform_volume* v, int use_iso, double iso) {
  isoform_contour_options o;
  isoform_mesh* m = NULL;
  isoform_contour_options_default(&o);
  o.threads = 2;
  if (use_iso) {
    o.auto_isovalue = 0;
    o.isovalue = iso;
  }
  CHECK(isoform_contour(v, isoform_volume_find_grid(v, NULL), &o, NULL, &m) == ISOFORM_OK);
  return m;
}

static void reduce_90(isoform_mesh* m, const char* what) {
  isoform_mesh_stats before, after;
  isoform_reduce_stats r;
  isoform_reduce_options o;
  CHECK(isoform_mesh_stats_get(m, &before) == ISOFORM_OK);
  isoform_reduce_options_default(&o);
  CHECK(o.keep_fraction == 0.1);
  CHECK(isoform_reduce(m, &o, NULL) == ISOFORM_OK);
  CHECK(isoform_mesh_stats_get(m, &after) == ISOFORM_OK);
  CHECK(isoform_mesh_reduce_stats(m, &r) == ISOFORM_OK);
  printf("%s: %lld -> %lld triangles, %lld parts, chi %lld -> %lld, %d passes, %lld swaps\n", what,
         before.triangles, after.triangles, after.parts, before.euler_characteristic, after.euler_characteristic,
         r.passes, r.swaps);
  CHECK(r.triangles_before == before.triangles && r.triangles_after == after.triangles);
  CHECK(after.triangles <= before.triangles / 10 + 1);
  CHECK(after.boundary_edges == 0 && after.nonmanifold_edges == 0 && after.inconsistent_edges == 0);
  CHECK(after.degenerate_triangles == 0);
  CHECK(after.euler_characteristic == before.euler_characteristic);
  CHECK(after.parts == before.parts);
  CHECK(isoform_mesh_has_curvature(m));
  CHECK(r.curvature_computed == 1);
}

static void case_cube(void) {
  isoform_volume* v = NULL;
  isoform_mesh* m;
  CHECK(isoform_volume_open(data_path("cube.vdb"), &v) == ISOFORM_OK);
  if (!v) return;
  m = contour(v, 0, 0.0);
  reduce_90(m, "cube.vdb");
  isoform_mesh_free(m);
  isoform_volume_free(v);
}

/* As test_realdata: the raw scan saved as a sparse VDB, whose contours close
 * where the scan ends. */
static void case_headsq(const char* dir) {
  isoform_raw_options o;
  isoform_volume *raw = NULL, *v = NULL;
  isoform_mesh* m;
  char vdb[1024];
  mkdir(dir, 0755);
  snprintf(vdb, sizeof vdb, "%s/head.vdb", dir);
  isoform_raw_options_default(&o);
  o.dims[0] = 64; o.dims[1] = 64; o.dims[2] = 93;
  o.scalar_type = ISOFORM_U16;
  o.spacing[0] = 3.2; o.spacing[1] = 3.2; o.spacing[2] = 1.5;
  CHECK(isoform_volume_open_raw(data_path("headsq_64x64x93_u16le.raw"), &o, &raw) == ISOFORM_OK);
  if (!raw) return;
  CHECK(isoform_volume_save_vdb(raw, vdb) == ISOFORM_OK);
  CHECK(isoform_volume_open(vdb, &v) == ISOFORM_OK);
  if (!v) return;
  m = contour(v, 1, 1150.0);
  reduce_90(m, "headsq at 1150");
  isoform_mesh_free(m);
  isoform_volume_free(v);
  isoform_volume_free(raw);
  unlink(vdb);
}

static void case_contract(void) {
  /* A square of two triangles, and a fin: three triangles on edge (0, 1). */
  const float square[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const int32_t two[6] = {0, 1, 2, 0, 2, 3};
  const float fin_points[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  const int32_t fin[9] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  isoform_mesh* m = NULL;
  isoform_reduce_options o;
  isoform_reduce_stats s;
  isoform_progress progress;
  isoform_reduce_options_default(&o);
  CHECK(o.keep_fraction == 0.1 && o.tolerance == 0.0 && o.lock_boundary == 0 &&
        o.point_method == ISOFORM_REDUCE_POINT_QUADRATIC && o.swaps == 1 && o.graph == 0);
  CHECK(isoform_reduce(NULL, &o, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(isoform_mesh_from_arrays(square, 4, two, 2, &m) == ISOFORM_OK);
  CHECK(isoform_mesh_reduce_stats(m, &s) == ISOFORM_ERR_INVALID_ARGUMENT);
  o.keep_fraction = 0.0;
  CHECK(isoform_reduce(m, &o, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(strstr(isoform_last_error(), "keep_fraction") != NULL);
  o.keep_fraction = 0.5;
  o.point_method = 7;
  CHECK(isoform_reduce(m, &o, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  o.point_method = ISOFORM_REDUCE_POINT_QUADRIC;
  memset(&progress, 0, sizeof progress);
  CHECK(isoform_reduce(m, &o, &progress) == ISOFORM_OK);
  CHECK(progress.stage == ISOFORM_STAGE_DONE);
  CHECK(isoform_mesh_reduce_stats(m, &s) == ISOFORM_OK);
  /* Two triangles on a boundary: removing one takes the other along, which
   * would leave nothing, so nothing is removable. */
  CHECK(s.triangles_before == 2 && s.triangles_after == 2 && s.stop_reason == 1);
  CHECK(isoform_mesh_triangle_count(m) == 2);
  isoform_mesh_free(m);
  m = NULL;
  CHECK(isoform_mesh_from_arrays(fin_points, 5, fin, 3, &m) == ISOFORM_OK);
  CHECK(isoform_reduce(m, NULL, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(strstr(isoform_last_error(), "edge (0, 1)") != NULL);
  CHECK(isoform_mesh_triangle_count(m) == 3);
  isoform_mesh_free(m);
}

int main(int argc, char** argv) {
  const char* which = argc > 1 ? argv[1] : "";
  if (!strcmp(which, "contract")) case_contract();
  else if (!strcmp(which, "cube")) case_cube();
  else if (!strcmp(which, "headsq")) case_headsq(argc > 2 ? argv[2] : ".");
  else {
    fprintf(stderr, "usage: test_capi_reduce contract|cube|headsq\n");
    return 2;
  }
  return check_failures ? 1 : 0;
}
