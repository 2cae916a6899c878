/* The reduction (Chapter 5) through the C API: the options' defaults and
 * refusals, the stats, and real contours (cube.vdb, headsq at the bone
 * level 1150) reduced by 90 %: closed, manifold, same Euler characteristic
 * (genus) and parts; bad input (an overlap, NaN, a fin with and without
 * manifold_parts_only), a single triangle, keep 1 and a boundary.
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

/* An n x n grid of z = .4 (x^2 + y^2) over [-1, 1]^2: a disk with 4 (n - 1) boundary edges. */
static isoform_mesh* paraboloid_grid(int n) {
  float* points = malloc(sizeof(float) * 3 * (size_t)(n * n));
  int32_t* triangles = malloc(sizeof(int32_t) * 6 * (size_t)((n - 1) * (n - 1)));
  isoform_mesh* m = NULL;
  int i, j, t = 0;
  for (j = 0; j < n; ++j)
    for (i = 0; i < n; ++i) {
      const float x = -1.0f + 2.0f * (float)i / (float)(n - 1), y = -1.0f + 2.0f * (float)j / (float)(n - 1);
      points[3 * (j * n + i)] = x;
      points[3 * (j * n + i) + 1] = y;
      points[3 * (j * n + i) + 2] = 0.4f * (x * x + y * y);
    }
  for (j = 0; j + 1 < n; ++j)
    for (i = 0; i + 1 < n; ++i) {
      const int32_t a = j * n + i;
      const int32_t quad[6] = {a, a + 1, a + n + 1, a, a + n + 1, a + n};
      memcpy(triangles + 6 * t++, quad, sizeof quad);
    }
  CHECK(isoform_mesh_from_arrays(points, (size_t)(n * n), triangles, (size_t)t * 2, &m) == ISOFORM_OK);
  free(points);
  free(triangles);
  return m;
}

/* Bad input and the edge cases of the reduction, through the C API. */
static void case_input(void) {
  /* Two triangles that cross: the edge (3, 4) of the second pierces the first at (.5, .5, 0). */
  const float crossing[18] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0.5f, 0.5f, -1, 0.5f, 0.5f, 1, 0.6f, 0.6f, 0.5f};
  const int32_t two[6] = {0, 1, 2, 3, 4, 5};
  const float nan_points[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const int32_t one[3] = {0, 1, 2};
  /* An octahedron (closed), and beside it a fin of three triangles on edge (6, 7). */
  const float octa_fin[33] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1,
                              5, 0, 0, 6, 0, 0, 5, 1, 0, 5, -1, 0, 5, 0, 1};
  const int32_t octa_fin_triangles[33] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5,
                                          6, 7, 8, 7, 6, 9, 6, 7, 10};
  float before[33], after[33];
  int32_t tri_before[33], tri_after[33];
  float bad[9];
  isoform_mesh *m = NULL, *locked = NULL;
  isoform_reduce_options o;
  isoform_reduce_stats s;
  isoform_mesh_stats ms;
  long long rim;

  CHECK(isoform_mesh_from_arrays(crossing, 6, two, 2, &m) == ISOFORM_OK);
  CHECK(isoform_reduce(m, NULL, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(strstr(isoform_last_error(), "the mesh overlaps itself: triangles 0 and 1 intersect (near 0.5, 0.5, 0)") != NULL);
  CHECK(isoform_mesh_triangle_count(m) == 2);
  isoform_mesh_free(m);

  /* NaN coordinates never reach the reduction: the mesh is refused, naming the vertex. */
  memcpy(bad, nan_points, sizeof bad);
  bad[4] = (float)NAN;
  m = NULL;
  CHECK(isoform_mesh_from_arrays(bad, 3, one, 1, &m) != ISOFORM_OK && m == NULL);
  CHECK(strstr(isoform_last_error(), "vertex 1 has a coordinate that is NaN or infinite") != NULL);

  /* A single triangle: an unchanged copy. */
  CHECK(isoform_mesh_from_arrays(nan_points, 3, one, 1, &m) == ISOFORM_OK);
  CHECK(isoform_reduce(m, NULL, NULL) == ISOFORM_OK);
  CHECK(isoform_mesh_reduce_stats(m, &s) == ISOFORM_OK);
  CHECK(s.triangles_after == 1 && s.removals == 0 && isoform_mesh_vertex_count(m) == 3);
  CHECK(isoform_mesh_copy_points(m, after) == ISOFORM_OK && memcmp(after, nan_points, sizeof nan_points) == 0);
  isoform_mesh_free(m);

  /* keep_fraction 1: the same points and triangles, bit for bit. */
  CHECK(isoform_mesh_from_arrays(octa_fin, 6, octa_fin_triangles, 8, &m) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_points(m, before) == ISOFORM_OK && isoform_mesh_copy_triangles(m, tri_before) == ISOFORM_OK);
  isoform_reduce_options_default(&o);
  CHECK(o.manifold_parts_only == 0);
  o.keep_fraction = 1.0;
  CHECK(isoform_reduce(m, &o, NULL) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_points(m, after) == ISOFORM_OK && isoform_mesh_copy_triangles(m, tri_after) == ISOFORM_OK);
  CHECK(memcmp(before, after, 18 * sizeof(float)) == 0 && memcmp(tri_before, tri_after, 24 * sizeof(int32_t)) == 0);
  CHECK(isoform_mesh_reduce_stats(m, &s) == ISOFORM_OK && s.removals == 0 && s.parts_left_alone == 0);
  CHECK(isoform_mesh_reduce_left_alone(m, 0) == NULL);
  isoform_mesh_free(m);

  /* The octahedron with a fin: refused, or with manifold_parts_only the fin is left alone. */
  CHECK(isoform_mesh_from_arrays(octa_fin, 11, octa_fin_triangles, 11, &m) == ISOFORM_OK);
  isoform_reduce_options_default(&o);
  o.keep_fraction = 0.5;
  CHECK(isoform_reduce(m, &o, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(strstr(isoform_last_error(), "edge (6, 7) is shared by 3 triangles") != NULL);
  o.manifold_parts_only = 1;
  CHECK(isoform_reduce(m, &o, NULL) == ISOFORM_OK);
  CHECK(isoform_mesh_reduce_stats(m, &s) == ISOFORM_OK);
  CHECK(s.parts_left_alone == 1 && s.triangles_left_alone == 3 && s.triangles_before == 11);
  CHECK(isoform_mesh_reduce_left_alone(m, 0) != NULL &&
        strcmp(isoform_mesh_reduce_left_alone(m, 0),
               "part of 3 triangles from triangle 8: the mesh is not manifold: edge (6, 7) is shared by 3 "
               "triangles") == 0);
  CHECK(isoform_mesh_reduce_left_alone(m, 1) == NULL && isoform_mesh_reduce_left_alone(NULL, 0) == NULL);
  /* Half of the octahedron's 8 triangles: one removal makes it a tetrahedron (4 vertices); the
   * fin's 5 vertices and 3 triangles follow unchanged. */
  CHECK(s.removals == 1 && isoform_mesh_triangle_count(m) == 7 && isoform_mesh_vertex_count(m) == 9);
  CHECK(isoform_mesh_copy_points(m, after) == ISOFORM_OK && isoform_mesh_copy_triangles(m, tri_after) == ISOFORM_OK);
  CHECK(memcmp(after + 12, octa_fin + 18, 15 * sizeof(float)) == 0);
  CHECK(tri_after[12] == 4 && tri_after[13] == 5 && tri_after[14] == 6 && tri_after[15] == 5 && tri_after[16] == 4 &&
        tri_after[17] == 7 && tri_after[18] == 4 && tri_after[19] == 5 && tri_after[20] == 8);
  isoform_mesh_free(m);

  /* A mesh with a boundary reduces; with lock_boundary every boundary edge stays. */
  m = paraboloid_grid(21);
  locked = paraboloid_grid(21);
  CHECK(isoform_mesh_stats_get(m, &ms) == ISOFORM_OK);
  rim = ms.boundary_edges;
  CHECK(rim == 80);
  isoform_reduce_options_default(&o);
  o.keep_fraction = 0.2;
  CHECK(isoform_reduce(m, &o, NULL) == ISOFORM_OK);
  CHECK(isoform_mesh_stats_get(m, &ms) == ISOFORM_OK);
  CHECK(ms.triangles <= 160 && ms.euler_characteristic == 1 && ms.boundary_edges < rim);
  o.lock_boundary = 1;
  CHECK(isoform_reduce(locked, &o, NULL) == ISOFORM_OK);
  CHECK(isoform_mesh_stats_get(locked, &ms) == ISOFORM_OK);
  CHECK(ms.euler_characteristic == 1 && ms.boundary_edges == rim && ms.triangles < 800);
  isoform_mesh_free(m);
  isoform_mesh_free(locked);
}

int main(int argc, char** argv) {
  const char* which = argc > 1 ? argv[1] : "";
  if (!strcmp(which, "contract")) case_contract();
  else if (!strcmp(which, "input")) case_input();
  else if (!strcmp(which, "cube")) case_cube();
  else if (!strcmp(which, "headsq")) case_headsq(argc > 2 ? argv[2] : ".");
  else {
    fprintf(stderr, "usage: test_capi_reduce contract|input|cube|headsq\n");
    return 2;
  }
  return check_failures ? 1 : 0;
}
