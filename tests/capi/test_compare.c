/* The comparison calls of isoform.h from C: options, the octahedron's flat
 * triangles and Loop surface against the unit sphere (exact figures), the
 * tessellation as a mesh, a volume reference, the report files, errors. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "isoform.h"

static isoform_mesh* octahedron(void) {
  static const double p[18] = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  static const int32_t t[24] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  isoform_mesh* m = NULL;
  CHECK(isoform_mesh_from_arrays_f64(p, 6, t, 8, &m) == ISOFORM_OK);
  return m;
}

static void test_options_default(void) {
  isoform_compare_options o;
  memset(&o, 0x7f, sizeof o);
  isoform_compare_options_default(&o);
  CHECK(o.level == 8 && o.reference == ISOFORM_REFERENCE_NONE && o.fit_reference == 1);
  CHECK(o.radius == 1.0 && o.minor_radius == 0.25 && o.grid == -1 && o.isovalue == 0.0);
  CHECK(o.loop_isolation == 6 && o.loop_sharp_corners == 1 && o.table_triangles == 2000);
  CHECK(o.input_name == NULL);
}

static void test_octahedron(void) {
  isoform_mesh* m = octahedron();
  isoform_compare_options o;
  isoform_compare_report* r = NULL;
  isoform_compare_metrics flat, loop;
  isoform_mesh* tess = NULL;
  isoform_mesh_stats stats;
  isoform_progress progress = {0.0f, 0, 0};
  isoform_compare_options_default(&o);
  o.level = 3;
  o.reference = ISOFORM_REFERENCE_SPHERE;
  o.fit_reference = 0; /* the unit sphere about the origin */
  CHECK(isoform_compare(m, NULL, &o, &progress, &r) == ISOFORM_OK);
  CHECK(progress.stage == ISOFORM_STAGE_DONE);
  CHECK(isoform_compare_report_surface_count(r) == 3);
  CHECK(strcmp(isoform_compare_report_surface_name(r, 0), "linear") == 0);
  CHECK(strcmp(isoform_compare_report_surface_name(r, 1), "loop") == 0);
  CHECK(strcmp(isoform_compare_report_surface_name(r, 2), "side-vertex") == 0);
  CHECK(isoform_compare_report_surface_name(r, 3) == NULL);
  CHECK(strcmp(isoform_compare_report_notes(r), "") == 0);
  CHECK(strcmp(isoform_compare_report_deviation_unit(r), "world units") == 0);
  CHECK(strstr(isoform_compare_report_reference(r), "radius 1") != NULL);
  CHECK(isoform_compare_report_metrics(r, 0, &flat) == ISOFORM_OK);
  CHECK(isoform_compare_report_metrics(r, 1, &loop) == ISOFORM_OK);
  CHECK(flat.samples == 80 && loop.samples == 80 && flat.failed_samples == 0);
  CHECK(fabs(flat.deviation.max - (1.0 - 1.0 / sqrt(3.0))) < 1e-15);
  CHECK(flat.data_point_error.max == 0.0);
  CHECK(fabs(flat.normal_gap.max - acos(1.0 / 3.0)) < 1e-14);
  /* Loop's limit point of a valence-4 vertex lies 1 - 4 chi from the centre:
   * chi = 1 / (4 + 3 / (8 beta)), beta = (5/8 - (3/8)^2) / 4. */
  {
    const double beta = (5.0 / 8.0 - 9.0 / 64.0) / 4.0, chi = 1.0 / (4.0 + 3.0 / (8.0 * beta));
    CHECK(fabs(loop.data_point_error.max - 4.0 * chi) < 1e-12);
    CHECK(fabs(loop.data_point_error.rms - 4.0 * chi) < 1e-12);
  }
  CHECK(loop.normal_gap.max < 1e-9);
  CHECK(loop.mean_curvature.p50 > 0.5);
  CHECK(loop.tessellation_triangles == 72);
  /* The side-vertex surface passes through the vertices and is tangent-plane
   * continuous across the edges. */
  {
    isoform_compare_metrics sv;
    CHECK(isoform_compare_report_metrics(r, 2, &sv) == ISOFORM_OK);
    CHECK(sv.data_point_error.max < 1e-12);
    CHECK(sv.normal_gap.max < 1e-6);
    CHECK(sv.deviation.max < flat.deviation.max);
  }
  CHECK(isoform_compare_report_metrics(r, 5, &loop) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(isoform_compare_report_tessellation(r, 1, &tess) == ISOFORM_OK);
  CHECK(isoform_mesh_triangle_count(tess) == 72);
  CHECK(isoform_mesh_vertex_count(tess) == 6 + 12 * 2 + 8);
  CHECK(isoform_mesh_stats_get(tess, &stats) == ISOFORM_OK);
  CHECK(stats.boundary_edges == 0 && stats.nonmanifold_edges == 0 && stats.euler_characteristic == 2);
  isoform_mesh_free(tess);
  isoform_compare_report_free(r);
  isoform_mesh_free(m);
}

/* A level-set sphere of radius 5 in a 24^3 array (spacing 0.5), its contour
 * compared with the volume itself: the flat contour lies on the trilinear
 * contour at its vertices, within a small fraction of a voxel between. */
static void test_volume_reference(void) {
  static float values[24 * 24 * 24];
  int i, j, k;
  isoform_volume* v = NULL;
  isoform_mesh* m = NULL;
  isoform_compare_report* r = NULL;
  isoform_compare_options o;
  isoform_compare_metrics flat;
  const double spacing[3] = {0.5, 0.5, 0.5}, origin[3] = {-6, -6, -6};
  for (k = 0; k < 24; ++k)
    for (j = 0; j < 24; ++j)
      for (i = 0; i < 24; ++i) {
        const double x = -6 + 0.5 * i - 0.1, y = -6 + 0.5 * j + 0.05, z = -6 + 0.5 * k;
        values[(k * 24 + j) * 24 + i] = (float)(sqrt(x * x + y * y + z * z) - 5.0);
      }
  CHECK(isoform_volume_from_dense(values, 24, 24, 24, spacing, origin, "sdf", ISOFORM_CLASS_LEVEL_SET, &v) ==
        ISOFORM_OK);
  CHECK(isoform_contour(v, 0, NULL, NULL, &m) == ISOFORM_OK);
  isoform_compare_options_default(&o);
  o.level = 2;
  CHECK(isoform_compare(m, v, &o, NULL, &r) == ISOFORM_OK);
  CHECK(strcmp(isoform_compare_report_deviation_unit(r), "voxels") == 0);
  CHECK(isoform_compare_report_metrics(r, 0, &flat) == ISOFORM_OK);
  CHECK(flat.deviation.count == flat.samples && flat.deviation.max < 0.1);
  isoform_compare_report_free(r);
  o.reference = ISOFORM_REFERENCE_VOLUME;
  CHECK(isoform_compare(m, NULL, &o, NULL, &r) == ISOFORM_ERR_INVALID_ARGUMENT && r == NULL);
  isoform_mesh_free(m);
  isoform_volume_free(v);
}

static void test_write_and_errors(const char* dir) {
  isoform_mesh* m = octahedron();
  isoform_compare_report* r = NULL;
  isoform_compare_options o;
  char path[4096];
  struct stat st;
  isoform_compare_options_default(&o);
  o.level = 2;
  CHECK(isoform_compare(NULL, NULL, &o, NULL, &r) == ISOFORM_ERR_INVALID_ARGUMENT);
  o.level = 0;
  CHECK(isoform_compare(m, NULL, &o, NULL, &r) == ISOFORM_ERR_INVALID_ARGUMENT && r == NULL);
  CHECK(strstr(isoform_last_error(), "level") != NULL);
  o.level = 2;
  o.reference = ISOFORM_REFERENCE_TORUS;
  o.fit_reference = 0;
  o.radius = 0.1; /* major < minor */
  CHECK(isoform_compare(m, NULL, &o, NULL, &r) == ISOFORM_ERR_INVALID_ARGUMENT && r == NULL);
  o.reference = ISOFORM_REFERENCE_NONE;
  CHECK(isoform_compare(m, NULL, &o, NULL, &r) == ISOFORM_OK);
  snprintf(path, sizeof path, "%s/no-such-folder", dir);
  CHECK(isoform_compare_report_write(r, path) == ISOFORM_ERR_IO);
  CHECK(strstr(isoform_last_error(), "no-such-folder") != NULL);
  mkdir(dir, 0755);
  CHECK(isoform_compare_report_write(r, dir) == ISOFORM_OK);
  snprintf(path, sizeof path, "%s/report.json", dir);
  CHECK(stat(path, &st) == 0 && st.st_size > 100);
  snprintf(path, sizeof path, "%s/samples.csv", dir);
  CHECK(stat(path, &st) == 0 && st.st_size > 100);
  snprintf(path, sizeof path, "%s/report.md", dir);
  CHECK(stat(path, &st) == 0 && st.st_size > 100);
  isoform_compare_report_free(r);
  isoform_compare_report_free(NULL);
  isoform_mesh_free(m);
}

int main(int argc, char** argv) {
  test_options_default();
  test_octahedron();
  test_volume_reference();
  test_write_and_errors(argc > 1 ? argv[1] : "compare-out");
  if (check_failures) fprintf(stderr, "%d checks failed\n", check_failures);
  return check_failures ? 1 : 0;
}
