/* The real files of ../shared/data through the C API: closed, manifold,
 * consistently oriented contours; the level-set sphere within half a voxel
 * of its radius; clear errors on damaged input.
 * Usage: test_realdata CASE SCRATCH_DIR */
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

static isoform_mesh* contour_file(isoform_volume* v, const char* grid, int use_iso, double iso) {
  isoform_contour_options o;
  isoform_mesh* m = NULL;
  const int index = isoform_volume_find_grid(v, grid);
  CHECK(index >= 0);
  isoform_contour_options_default(&o);
  o.threads = 2;
  if (use_iso) {
    o.auto_isovalue = 0;
    o.isovalue = iso;
  }
  CHECK(isoform_contour(v, index, &o, NULL, &m) == ISOFORM_OK);
  return m;
}

static void expect_closed_manifold(const isoform_mesh* m, const char* what) {
  isoform_mesh_stats s;
  CHECK(isoform_mesh_stats_get(m, &s) == ISOFORM_OK);
  printf("%s: %lld vertices, %lld triangles, %lld parts, chi %lld, %lld ambiguous faces "
         "(%lld degenerate saddles), %lld extra points, %lld centroids\n",
         what, s.vertices, s.triangles, s.parts, s.euler_characteristic, s.ambiguous_faces, s.degenerate_saddles,
         s.extra_points, s.centroid_points);
  CHECK(s.triangles > 0);
  CHECK(s.boundary_edges == 0);
  CHECK(s.nonmanifold_edges == 0);
  CHECK(s.inconsistent_edges == 0);
  CHECK(s.degenerate_triangles == 0);
}

static void case_sphere(void) {
  isoform_volume* v = NULL;
  isoform_mesh* m;
  isoform_mesh_stats s;
  size_t n, i;
  float* p;
  double mean = 0, worst = 0;
  CHECK(isoform_volume_open(data_path("sphere.vdb"), &v) == ISOFORM_OK);
  if (!v) return;
  m = contour_file(v, "ls_sphere", 0, 0.0);
  expect_closed_manifold(m, "sphere.vdb");
  CHECK(isoform_mesh_stats_get(m, &s) == ISOFORM_OK);
  CHECK(s.parts == 1 && s.euler_characteristic == 2);
  n = isoform_mesh_vertex_count(m);
  p = malloc(3 * n * sizeof(float));
  CHECK(isoform_mesh_copy_points(m, p) == ISOFORM_OK);
  for (i = 0; i < n; ++i) mean += sqrt(p[3 * i] * p[3 * i] + p[3 * i + 1] * p[3 * i + 1] + p[3 * i + 2] * p[3 * i + 2]);
  mean /= (double)n;
  /* The file's sphere has radius 3 world units (60 voxels of 0.05). */
  for (i = 0; i < n; ++i) {
    const double r = sqrt(p[3 * i] * p[3 * i] + p[3 * i + 1] * p[3 * i + 1] + p[3 * i + 2] * p[3 * i + 2]);
    if (fabs(r - 3.0) > worst) worst = fabs(r - 3.0);
  }
  printf("sphere.vdb: mean radius %.5f, largest deviation from 3 %.5f (half a voxel is 0.025)\n", mean, worst);
  CHECK(worst < 0.025);
  CHECK(fabs(mean - 3.0) < 0.005);
  free(p);
  isoform_mesh_free(m);
  isoform_volume_free(v);
}

static void case_file(const char* file, const char* grid, int use_iso, double iso) {
  isoform_volume* v = NULL;
  isoform_mesh* m;
  CHECK(isoform_volume_open(data_path(file), &v) == ISOFORM_OK);
  if (!v) return;
  m = contour_file(v, grid, use_iso, iso);
  expect_closed_manifold(m, file);
  isoform_mesh_free(m);
  isoform_volume_free(v);
}

static void case_headsq(const char* dir) {
  isoform_raw_options o;
  isoform_volume *raw = NULL, *v = NULL;
  char vdb[1024];
  const double levels[2] = {500.0, 1150.0};
  int l;
  snprintf(vdb, sizeof vdb, "%s/head.vdb", dir);
  isoform_raw_options_default(&o);
  o.dims[0] = 64; o.dims[1] = 64; o.dims[2] = 93;
  o.scalar_type = ISOFORM_U16;
  o.spacing[0] = 3.2; o.spacing[1] = 3.2; o.spacing[2] = 1.5;
  CHECK(isoform_volume_open_raw(data_path("headsq_64x64x93_u16le.raw"), &o, &raw) == ISOFORM_OK);
  CHECK(isoform_volume_save_vdb(raw, vdb) == ISOFORM_OK);
  CHECK(isoform_volume_open(vdb, &v) == ISOFORM_OK);
  if (!v) return;
  for (l = 0; l < 2; ++l) {
    isoform_mesh* m = contour_file(v, NULL, 1, levels[l]);
    expect_closed_manifold(m, levels[l] == 500.0 ? "headsq at 500" : "headsq at 1150");
    isoform_mesh_free(m);
  }
  isoform_volume_free(v);
  isoform_volume_free(raw);
  unlink(vdb);
}

/* Copies the first `keep` bytes of src to dst. */
static void truncated_copy(const char* src, const char* dst, long keep) {
  FILE* in = fopen(src, "rb");
  FILE* out = fopen(dst, "wb");
  char buf[65536];
  long left = keep;
  CHECK(in && out);
  if (!in || !out) return;
  while (left > 0) {
    const size_t n = fread(buf, 1, left < (long)sizeof buf ? (size_t)left : sizeof buf, in);
    if (n == 0) break;
    fwrite(buf, 1, n, out);
    left -= (long)n;
  }
  fclose(in);
  fclose(out);
}

static void case_bad_inputs(const char* dir) {
  char path[1024];
  isoform_volume* v = NULL;
  isoform_mesh* m = NULL;
  isoform_contour_options o;
  FILE* f;
  snprintf(path, sizeof path, "%s/missing.vdb", dir);
  CHECK(isoform_volume_open(path, &v) == ISOFORM_ERR_IO && v == NULL);
  CHECK(strstr(isoform_last_error(), "missing.vdb") != NULL);

  snprintf(path, sizeof path, "%s/notes.vdb", dir);
  f = fopen(path, "w");
  fputs("this is not a volume\n", f);
  fclose(f);
  CHECK(isoform_volume_open(path, &v) == ISOFORM_ERR_FORMAT && v == NULL);
  CHECK(strstr(isoform_last_error(), "notes.vdb") != NULL);

  /* A truncated file fails at open or when its grid is read, never crashes. */
  snprintf(path, sizeof path, "%s/truncated.vdb", dir);
  truncated_copy(data_path("sphere.vdb"), path, 500000);
  if (isoform_volume_open(path, &v) == ISOFORM_OK) {
    isoform_contour_options_default(&o);
    CHECK(isoform_contour(v, 0, &o, NULL, &m) == ISOFORM_ERR_FORMAT && m == NULL);
    isoform_volume_free(v);
  }
  CHECK(strstr(isoform_last_error(), "truncated.vdb") != NULL);

  CHECK(isoform_volume_open(data_path("sphere.vdb"), &v) == ISOFORM_OK);
  CHECK(isoform_volume_find_grid(v, "density") == -1);
  CHECK(strstr(isoform_last_error(), "ls_sphere") != NULL);
  isoform_contour_options_default(&o);
  o.auto_isovalue = 0;
  o.isovalue = 99.0;
  CHECK(isoform_contour(v, 0, &o, NULL, &m) == ISOFORM_OK);
  CHECK(isoform_mesh_triangle_count(m) == 0);
  isoform_mesh_free(m);
  isoform_volume_free(v);
}

int main(int argc, char** argv) {
  const char* which = argc > 1 ? argv[1] : "";
  const char* dir = argc > 2 ? argv[2] : "/tmp";
  mkdir(dir, 0755);
  if (!strcmp(which, "sphere")) case_sphere();
  else if (!strcmp(which, "cube")) case_file("cube.vdb", "ls_cube", 0, 0.0);
  else if (!strcmp(which, "smoke")) case_file("smoke.vdb", "density", 1, 0.5);
  else if (!strcmp(which, "headsq")) case_headsq(dir);
  else if (!strcmp(which, "bad_inputs")) case_bad_inputs(dir);
  else {
    fprintf(stderr, "usage: test_realdata sphere|cube|smoke|headsq|bad_inputs DIR\n");
    return 2;
  }
  if (check_failures) fprintf(stderr, "%d checks failed\n", check_failures);
  return check_failures ? 1 : 0;
}
