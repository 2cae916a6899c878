/* The contract of isoform.h from C: versions, errors, handles, options,
 * copy-out calls, meshes from arrays, files. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "isoform.h"

static void test_version_and_errors(void) {
  isoform_volume* v = NULL;
  CHECK(isoform_version() == ISOFORM_VERSION);
  CHECK(strcmp(isoform_status_name(ISOFORM_ERR_IO), "io error") == 0);
  CHECK(isoform_volume_open("/nonexistent/scan.vdb", &v) == ISOFORM_ERR_IO);
  CHECK(v == NULL);
  CHECK(strstr(isoform_last_error(), "/nonexistent/scan.vdb") != NULL);
  CHECK(isoform_volume_open(NULL, &v) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(isoform_contour(NULL, 0, NULL, NULL, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  isoform_volume_free(NULL);
  isoform_mesh_free(NULL);
}

/* A sphere of radius 6 in a 16^3 dense array, as a level set. */
static isoform_volume* sphere_volume(void) {
  static float values[16 * 16 * 16];
  int i, j, k;
  isoform_volume* v = NULL;
  const double spacing[3] = {0.5, 0.5, 0.5}, origin[3] = {-4, -4, -4};
  for (k = 0; k < 16; ++k)
    for (j = 0; j < 16; ++j)
      for (i = 0; i < 16; ++i)
        values[(k * 16 + j) * 16 + i] =
            (float)(sqrt((i - 7.5) * (i - 7.5) + (j - 7.3) * (j - 7.3) + (k - 7.6) * (k - 7.6)) - 6.0);
  CHECK(isoform_volume_from_dense(values, 16, 16, 16, spacing, origin, "sdf", ISOFORM_CLASS_LEVEL_SET, &v) ==
        ISOFORM_OK);
  return v;
}

static void test_dense_contour_and_copy_out(void) {
  isoform_volume* v = sphere_volume();
  isoform_grid_info info;
  isoform_contour_options o;
  isoform_progress progress;
  isoform_mesh* m = NULL;
  isoform_mesh_stats s;
  size_t n, t, i;
  float *points, *normals;
  int32_t *tris, *nbrs, *parts;
  if (!v) return;
  CHECK(isoform_volume_grid_count(v) == 1);
  CHECK(isoform_volume_grid_info(v, 0, &info) == ISOFORM_OK);
  CHECK(strcmp(info.name, "sdf") == 0);
  CHECK(info.grid_class == ISOFORM_CLASS_LEVEL_SET);
  CHECK(info.voxel_size[0] == 0.5 && info.transform[3] == -4.0);
  CHECK(isoform_volume_grid_info(v, 1, &info) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(isoform_volume_find_grid(v, NULL) == 0);
  CHECK(isoform_volume_find_grid(v, "density") == -1);
  CHECK(strstr(isoform_last_error(), "'sdf'") != NULL);

  isoform_contour_options_default(&o);
  CHECK(o.auto_isovalue == 1 && o.method == ISOFORM_METHOD_CELLS && o.threads == 0);
  memset(&progress, 0, sizeof(progress));
  CHECK(isoform_contour(v, 0, &o, &progress, &m) == ISOFORM_OK);
  CHECK(progress.stage == ISOFORM_STAGE_DONE);
  CHECK(isoform_mesh_stats_get(m, &s) == ISOFORM_OK);
  CHECK(s.isovalue == 0.0 && s.isovalue_was_auto == 1);
  CHECK(s.boundary_edges == 0 && s.nonmanifold_edges == 0 && s.inconsistent_edges == 0);
  CHECK(s.euler_characteristic == 2 && s.parts == 1);
  n = isoform_mesh_vertex_count(m);
  t = isoform_mesh_triangle_count(m);
  CHECK(n > 100 && t == 2 * n - 4);
  points = malloc(3 * n * sizeof(float));
  normals = malloc(3 * n * sizeof(float));
  tris = malloc(3 * t * sizeof(int32_t));
  nbrs = malloc(3 * t * sizeof(int32_t));
  parts = malloc(t * sizeof(int32_t));
  CHECK(isoform_mesh_copy_points(m, points) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_normals(m, normals) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_triangles(m, tris) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_neighbours(m, nbrs) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_parts(m, parts) == ISOFORM_OK);
  for (i = 0; i < n; ++i) {
    /* World coordinates: centre (-0.25, -0.35, -0.2), radius 3 world units. */
    const double x = points[3 * i] + 0.25, y = points[3 * i + 1] + 0.35, z = points[3 * i + 2] + 0.2;
    const double r = sqrt(x * x + y * y + z * z);
    CHECK(fabs(r - 3.0) < 0.05);
    CHECK((x * normals[3 * i] + y * normals[3 * i + 1] + z * normals[3 * i + 2]) / r > 0.98);
  }
  for (i = 0; i < 3 * t; ++i) CHECK(nbrs[i] >= 0 && (size_t)nbrs[i] < t);
  for (i = 0; i < t; ++i) CHECK(parts[i] == 0);

  /* The same mesh through isoform_mesh_from_arrays: same topology, normals
   * estimated from the mesh (Remark 3.15) close to the volume's. */
  {
    isoform_mesh* m2 = NULL;
    isoform_mesh_stats s2;
    float* est = malloc(3 * n * sizeof(float));
    CHECK(isoform_mesh_from_arrays(points, n, tris, t, &m2) == ISOFORM_OK);
    CHECK(isoform_mesh_stats_get(m2, &s2) == ISOFORM_OK);
    CHECK(s2.euler_characteristic == 2 && s2.boundary_edges == 0 && s2.parts == 1);
    CHECK(isoform_mesh_copy_normals(m2, est) == ISOFORM_OK);
    for (i = 0; i < n; ++i)
      CHECK(est[3 * i] * normals[3 * i] + est[3 * i + 1] * normals[3 * i + 1] + est[3 * i + 2] * normals[3 * i + 2] >
            0.9);
    free(est);
    isoform_mesh_free(m2);
    tris[0] = (int32_t)n; /* out of range */
    CHECK(isoform_mesh_from_arrays(points, n, tris, t, &m2) == ISOFORM_ERR_INVALID_ARGUMENT);
    CHECK(m2 == NULL);
  }
  free(points);
  free(normals);
  free(tris);
  free(nbrs);
  free(parts);
  isoform_mesh_free(m);
  isoform_volume_free(v);
}

static void test_options_and_cancel(void) {
  isoform_volume* v = sphere_volume();
  isoform_contour_options o;
  isoform_progress progress;
  isoform_mesh* m = NULL;
  isoform_contour_options_default(&o);
  o.method = 7;
  CHECK(isoform_contour(v, 0, &o, NULL, &m) == ISOFORM_ERR_INVALID_ARGUMENT);
  isoform_contour_options_default(&o);
  CHECK(isoform_contour(v, 3, &o, NULL, &m) == ISOFORM_ERR_INVALID_ARGUMENT);
  memset(&progress, 0, sizeof(progress));
  progress.cancel = 1;
  CHECK(isoform_contour(v, 0, &o, &progress, &m) == ISOFORM_ERR_CANCELLED);
  CHECK(m == NULL);
  o.auto_isovalue = 0;
  o.isovalue = 100.0; /* beyond every sample: an empty mesh, not an error */
  CHECK(isoform_contour(v, 0, &o, NULL, &m) == ISOFORM_OK);
  CHECK(isoform_mesh_triangle_count(m) == 0);
  isoform_mesh_free(m);
  o.isovalue = NAN;
  CHECK(isoform_contour(v, 0, &o, NULL, &m) == ISOFORM_ERR_INVALID_ARGUMENT);
  isoform_volume_free(v);
  {
    float bad[8] = {0, 1, 2, 3, 4, NAN, 6, 7};
    CHECK(isoform_volume_from_dense(bad, 2, 2, 2, NULL, NULL, NULL, 0, &v) == ISOFORM_ERR_FORMAT);
    CHECK(strstr(isoform_last_error(), "NaN") != NULL);
  }
}

static void test_phantom_files_round_trip(void) {
  char dir[] = "/tmp/isoform-capi-XXXXXX";
  char vdb[256], ply[256], obj[256], stl[256];
  isoform_volume *v = NULL, *back = NULL;
  isoform_mesh *m = NULL, *loaded = NULL;
  isoform_contour_options o;
  isoform_mesh_stats s, sl;
  char* paths[3];
  int e;
  CHECK(mkdtemp(dir) != NULL);
  snprintf(vdb, sizeof vdb, "%s/phantom.vdb", dir);
  snprintf(ply, sizeof ply, "%s/p.ply", dir);
  snprintf(obj, sizeof obj, "%s/p.obj", dir);
  snprintf(stl, sizeof stl, "%s/p.stl", dir);
  CHECK(isoform_volume_phantom(8, &v) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(isoform_volume_phantom(48, &v) == ISOFORM_OK);
  CHECK(isoform_volume_save_vdb(v, vdb) == ISOFORM_OK);
  CHECK(isoform_volume_open(vdb, &back) == ISOFORM_OK);
  isoform_contour_options_default(&o);
  o.auto_isovalue = 0;
  o.isovalue = 0.5;
  CHECK(isoform_contour(back, isoform_volume_find_grid(back, "density"), &o, NULL, &m) == ISOFORM_OK);
  CHECK(isoform_mesh_stats_get(m, &s) == ISOFORM_OK);
  CHECK(s.boundary_edges == 0 && s.nonmanifold_edges == 0 && s.inconsistent_edges == 0);
  CHECK(s.parts >= 2); /* the skull's outer and inner surfaces */
  paths[0] = ply; paths[1] = obj; paths[2] = stl;
  for (e = 0; e < 3; ++e) {
    CHECK(isoform_mesh_save(m, paths[e]) == ISOFORM_OK);
    CHECK(isoform_mesh_load(paths[e], &loaded) == ISOFORM_OK);
    CHECK(isoform_mesh_stats_get(loaded, &sl) == ISOFORM_OK);
    CHECK(sl.vertices == s.vertices && sl.triangles == s.triangles && sl.parts == s.parts);
    CHECK(sl.boundary_edges == 0 && sl.euler_characteristic == s.euler_characteristic);
    isoform_mesh_free(loaded);
    loaded = NULL;
    unlink(paths[e]);
  }
  CHECK(isoform_mesh_save(m, "/nonexistent-dir/x.ply") == ISOFORM_ERR_IO);
  CHECK(isoform_mesh_save(m, ply) == ISOFORM_OK);
  {
    /* A cancelled save: ISOFORM_ERR_CANCELLED, the file saved before kept
     * whole, and nothing else in the folder. */
    isoform_progress cancel = {0};
    long before = 0, after = 0;
    FILE* f = fopen(ply, "rb");
    CHECK(f != NULL);
    if (f) { fseek(f, 0, SEEK_END); before = ftell(f); fclose(f); }
    cancel.cancel = 1;
    CHECK(isoform_mesh_save_progress(m, obj, &cancel) == ISOFORM_ERR_CANCELLED);
    CHECK(access(obj, F_OK) != 0);
    CHECK(isoform_mesh_save_progress(m, ply, &cancel) == ISOFORM_ERR_CANCELLED);
    f = fopen(ply, "rb");
    CHECK(f != NULL);
    if (f) { fseek(f, 0, SEEK_END); after = ftell(f); fclose(f); }
    CHECK(before > 0 && after == before);
    CHECK(isoform_mesh_save_progress(m, obj, NULL) == ISOFORM_OK);
    CHECK(access(obj, F_OK) == 0);
    unlink(obj);
  }
  {
    char bad[300];
    snprintf(bad, sizeof bad, "%s/p.xyz", dir);
    CHECK(isoform_mesh_save(m, bad) == ISOFORM_ERR_INVALID_ARGUMENT);
    CHECK(access(bad, F_OK) != 0);
  }
  unlink(ply);
  unlink(vdb);
  CHECK(rmdir(dir) == 0); /* nothing left behind, no temporary files */
  isoform_mesh_free(m);
  isoform_volume_free(back);
  isoform_volume_free(v);
}

/* The memory budget: a grid whose decoded size passes it is refused with a
 * message naming the file and the budget; 0 restores the default. */
static void test_memory_budget(void) {
  char dir[] = "/tmp/isoform-capi-XXXXXX";
  char vdb[256];
  isoform_volume *v = NULL, *back = NULL;
  isoform_mesh* m = NULL;
  isoform_contour_options o;
  const unsigned long long fallback = isoform_memory_budget();
  CHECK(fallback >= (1ull << 28)); /* half of any machine that builds isoform */
  CHECK(mkdtemp(dir) != NULL);
  snprintf(vdb, sizeof vdb, "%s/phantom.vdb", dir);
  CHECK(isoform_volume_phantom(48, &v) == ISOFORM_OK);
  CHECK(isoform_volume_save_vdb(v, vdb) == ISOFORM_OK);
  isoform_contour_options_default(&o);
  isoform_set_memory_budget(100 << 10);
  CHECK(isoform_memory_budget() == (100 << 10));
  CHECK(isoform_volume_open(vdb, &back) == ISOFORM_OK);
  CHECK(isoform_contour(back, 0, &o, NULL, &m) == ISOFORM_ERR_FORMAT);
  CHECK(m == NULL);
  CHECK(strstr(isoform_last_error(), vdb) == isoform_last_error());
  CHECK(strstr(isoform_last_error(), "beyond the budget of 100.0 KiB") != NULL);
  isoform_set_memory_budget(0);
  CHECK(isoform_memory_budget() == fallback);
  CHECK(isoform_contour(back, 0, &o, NULL, &m) == ISOFORM_OK);
  CHECK(m != NULL && isoform_mesh_triangle_count(m) > 0);
  isoform_mesh_free(m);
  isoform_volume_free(back);
  isoform_volume_free(v);
  unlink(vdb);
  CHECK(rmdir(dir) == 0);
}

/* A 4-D NIfTI-1 of 2x2x2 u8 samples and 2 volumes (0..7, then 10..17),
 * sform (2, 3, 4 per voxel, offset 1, 2, 3) in millimetres, written byte by
 * byte in this machine's order. */
static void write_nifti_series(const char* path) {
  unsigned char header[352];
  short dims[8] = {4, 2, 2, 2, 2, 1, 1, 1};
  float pixdim[8] = {1, 2, 3, 4, 1, 1, 1, 1};
  float offset = 352, srow[12] = {2, 0, 0, 1, 0, 3, 0, 2, 0, 0, 4, 3};
  int size = 348;
  short datatype = 2, bitpix = 8, sform_code = 1;
  unsigned char samples[16];
  FILE* f = fopen(path, "wb");
  int i;
  memset(header, 0, sizeof header);
  memcpy(header, &size, 4);
  memcpy(header + 40, dims, sizeof dims);
  memcpy(header + 70, &datatype, 2);
  memcpy(header + 72, &bitpix, 2);
  memcpy(header + 76, pixdim, sizeof pixdim);
  memcpy(header + 108, &offset, 4);
  header[123] = 2; /* millimetres */
  memcpy(header + 254, &sform_code, 2);
  memcpy(header + 280, srow, sizeof srow);
  memcpy(header + 344, "n+1", 4);
  for (i = 0; i < 16; ++i) samples[i] = (unsigned char)(i < 8 ? i : i + 2);
  CHECK(f != NULL);
  if (!f) return;
  fwrite(header, 1, sizeof header, f);
  fwrite(samples, 1, sizeof samples, f);
  fclose(f);
}

/* Open options: a 4-D file needs a volume; struct_size guards the layout. */
static void test_open_options(void) {
  char dir[] = "/tmp/isoform-capi-XXXXXX";
  char path[256];
  isoform_volume* v = NULL;
  isoform_open_options o;
  isoform_grid_info info;
  CHECK(mkdtemp(dir) != NULL);
  snprintf(path, sizeof path, "%s/series.nii", dir);
  write_nifti_series(path);
  CHECK(isoform_volume_open(path, &v) == ISOFORM_ERR_UNSUPPORTED && v == NULL);
  CHECK(strstr(isoform_last_error(), "a 4-D NIfTI of 2 volumes (2x2x2x2)") != NULL);
  CHECK(strstr(isoform_last_error(), "--volume K") != NULL);
  CHECK(isoform_volume_open_with(path, NULL, &v) == ISOFORM_ERR_UNSUPPORTED);
  isoform_open_options_default(&o);
  CHECK(o.struct_size == sizeof o && o.volume == -1);
  o.volume = 1;
  CHECK(isoform_volume_open_with(path, &o, &v) == ISOFORM_OK);
  CHECK(isoform_volume_grid_info(v, 0, &info) == ISOFORM_OK);
  CHECK(info.value_min == 10 && info.value_max == 17);
  CHECK(strcmp(info.space, "RAS") == 0 && strcmp(info.unit, "mm") == 0);
  CHECK(info.transform[0] == 2 && info.transform[3] == 1 && info.transform[5] == 3 && info.transform[10] == 4);
  isoform_volume_free(v);
  v = NULL;
  o.volume = 2;
  CHECK(isoform_volume_open_with(path, &o, &v) == ISOFORM_ERR_INVALID_ARGUMENT && v == NULL);
  o.volume = -2;
  CHECK(isoform_volume_open_with(path, &o, &v) == ISOFORM_ERR_INVALID_ARGUMENT);
  o.volume = 0;
  o.struct_size = 0; /* never filled by _default() */
  CHECK(isoform_volume_open_with(path, &o, &v) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(strstr(isoform_last_error(), "struct_size") != NULL);
  o.struct_size = sizeof o + 64; /* a newer caller's larger struct: the known fields count */
  CHECK(isoform_volume_open_with(path, &o, &v) == ISOFORM_OK);
  CHECK(isoform_volume_grid_info(v, 0, &info) == ISOFORM_OK && info.value_max == 7);
  isoform_volume_free(v);
  unlink(path);
  CHECK(rmdir(dir) == 0);
}

/* A tetrahedron moved into LPS (a half turn) and mirrored (RAS to LAS):
 * points moved, still closed and consistently oriented, normals outward. */
static void test_mesh_transform(void) {
  const float points[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const int32_t triangles[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  const double lps[16] = {-1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const double las[16] = {-1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const double flat[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
  const double* maps[2] = {lps, las};
  int m;
  for (m = 0; m < 2; ++m) {
    isoform_mesh* mesh = NULL;
    isoform_mesh_stats stats;
    float moved[12], normals[12];
    int v;
    CHECK(isoform_mesh_from_arrays(points, 4, triangles, 4, &mesh) == ISOFORM_OK);
    CHECK(isoform_mesh_transform(mesh, maps[m]) == ISOFORM_OK);
    CHECK(isoform_mesh_copy_points(mesh, moved) == ISOFORM_OK);
    CHECK(isoform_mesh_copy_normals(mesh, normals) == ISOFORM_OK);
    CHECK(isoform_mesh_stats_get(mesh, &stats) == ISOFORM_OK);
    CHECK(stats.boundary_edges == 0 && stats.inconsistent_edges == 0 && stats.euler_characteristic == 2);
    for (v = 0; v < 4; ++v) {
      const double* t = maps[m];
      const float* p = points + 3 * v;
      /* the centroid maps to the moved centroid; normals point away from it */
      const double c[3] = {t[0] * 0.25 + t[3], t[5] * 0.25 + t[7], 0.25};
      CHECK(moved[3 * v] == (float)(t[0] * p[0] + t[3]) && moved[3 * v + 1] == (float)(t[5] * p[1] + t[7]));
      CHECK((moved[3 * v] - c[0]) * normals[3 * v] + (moved[3 * v + 1] - c[1]) * normals[3 * v + 1] +
                (moved[3 * v + 2] - c[2]) * normals[3 * v + 2] > 0);
    }
    CHECK(isoform_mesh_transform(mesh, flat) == ISOFORM_ERR_INVALID_ARGUMENT);
    CHECK(strstr(isoform_last_error(), "flattens space") != NULL);
    isoform_mesh_free(mesh);
  }
}

int main(void) {
  test_version_and_errors();
  test_dense_contour_and_copy_out();
  test_options_and_cancel();
  test_phantom_files_round_trip();
  test_memory_budget();
  test_open_options();
  test_mesh_transform();
  if (check_failures) fprintf(stderr, "%d checks failed\n", check_failures);
  return check_failures ? 1 : 0;
}
