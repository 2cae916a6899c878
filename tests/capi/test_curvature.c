/* The surface curvature calls of isoform.h from C: options, the contour of
 * a dense sphere, copy-out, colours, statistics, cancel, errors, and normals
 * set by the caller. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "isoform.h"

/* A level-set sphere of radius 5 (world units) in a 24^3 array, spacing 0.5. */
static isoform_mesh* sphere_contour(void) {
  static float values[24 * 24 * 24];
  int i, j, k;
  isoform_volume* v = NULL;
  isoform_mesh* m = NULL;
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
  isoform_volume_free(v);
  return m;
}

static void test_options_default(void) {
  isoform_curvature_options o;
  memset(&o, 0x7f, sizeof o);
  isoform_curvature_options_default(&o);
  CHECK(o.method == ISOFORM_CURVATURE_QUARTIC);
  CHECK(o.extra_rings == 0 && o.update_normals == 0 && o.threads == 0);
  CHECK(o.color_by == ISOFORM_CURVATURE_MEAN);
}

static void test_sphere(void) {
  isoform_mesh* m = sphere_contour();
  isoform_curvature_stats s;
  isoform_progress progress;
  size_t n, i, positive = 0;
  float *h, *k, *d1;
  uint8_t *colors, *flags;
  double h_err = 0, k_err = 0;
  if (!m) return;
  n = isoform_mesh_vertex_count(m);
  CHECK(isoform_mesh_has_curvature(m) == 0 && isoform_mesh_color_count(m) == 0);
  h = malloc(n * sizeof *h);
  CHECK(isoform_mesh_copy_curvature(m, ISOFORM_CURVATURE_MEAN, h) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(strstr(isoform_last_error(), "no curvature") != NULL);
  memset(&progress, 0, sizeof progress);
  CHECK(isoform_curvature(m, NULL, &progress) == ISOFORM_OK);
  CHECK(progress.stage == ISOFORM_STAGE_DONE);
  CHECK(isoform_mesh_has_curvature(m) == 1 && isoform_mesh_color_count(m) == n);
  CHECK(isoform_mesh_curvature_stats(m, &s) == ISOFORM_OK);
  CHECK(s.method == ISOFORM_CURVATURE_QUARTIC && s.vertices == (long long)n);
  CHECK(s.failed == 0 && s.isolated == 0 && s.boundary == 0);
  CHECK(s.color_min < 0 && s.color_max > 0 && fabs(s.color_min + s.color_max) < 1e-12);
  k = malloc(n * sizeof *k);
  d1 = malloc(3 * n * sizeof *d1);
  colors = malloc(4 * n);
  flags = malloc(n);
  CHECK(isoform_mesh_copy_curvature(m, ISOFORM_CURVATURE_MEAN, h) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_curvature(m, ISOFORM_CURVATURE_GAUSS, k) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_curvature(m, ISOFORM_CURVATURE_DIR1, d1) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_curvature(m, 7, h) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(isoform_mesh_copy_colors(m, colors) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_curvature_flags(m, flags) == ISOFORM_OK);
  for (i = 0; i < n; ++i) {
    h_err += (h[i] - 0.2) * (h[i] - 0.2);
    k_err += (k[i] - 0.04) * (k[i] - 0.04);
    positive += h[i] > 0;
    CHECK(fabs(d1[3 * i] * d1[3 * i] + d1[3 * i + 1] * d1[3 * i + 1] + d1[3 * i + 2] * d1[3 * i + 2] - 1) < 1e-4);
    CHECK(colors[4 * i + 3] == 255);
    CHECK(flags[i] == 0);
  }
  /* Outward normals, convex: H = 1/r = 0.2 within a few percent. */
  CHECK(positive == n);
  CHECK(sqrt(h_err / (double)n) < 0.01);
  CHECK(sqrt(k_err / (double)n) < 0.004);
  free(h), free(k), free(d1), free(colors), free(flags);
  isoform_mesh_free(m);
}

static void test_cancel_and_errors(void) {
  isoform_mesh* m = sphere_contour();
  isoform_curvature_options o;
  isoform_progress progress;
  if (!m) return;
  memset(&progress, 0, sizeof progress);
  progress.cancel = 1;
  CHECK(isoform_curvature(m, NULL, &progress) == ISOFORM_ERR_CANCELLED);
  CHECK(isoform_mesh_has_curvature(m) == 0);
  isoform_curvature_options_default(&o);
  o.method = 9;
  CHECK(isoform_curvature(m, &o, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(strstr(isoform_last_error(), "method") != NULL);
  isoform_curvature_options_default(&o);
  o.extra_rings = 20;
  CHECK(isoform_curvature(m, &o, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(isoform_mesh_has_curvature(m) == 0);
  CHECK(isoform_curvature(NULL, NULL, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  isoform_mesh_free(m);
}

/* Double-precision points: a plane's curvature is zero to rounding. */
static void test_plane_f64(void) {
  double p[5 * 5 * 3];
  int32_t t[4 * 4 * 6];
  int i, j, c = 0;
  isoform_mesh* m = NULL;
  float h[25];
  isoform_curvature_options o;
  for (j = 0; j < 5; ++j)
    for (i = 0; i < 5; ++i) {
      p[3 * (j * 5 + i)] = 0.1 * i + 1000.0;
      p[3 * (j * 5 + i) + 1] = 0.1 * j;
      p[3 * (j * 5 + i) + 2] = 0.2 * (0.1 * i + 0.1 * j);
    }
  for (j = 0; j < 4; ++j)
    for (i = 0; i < 4; ++i) {
      const int32_t a = j * 5 + i;
      t[c++] = a, t[c++] = a + 1, t[c++] = a + 6, t[c++] = a, t[c++] = a + 6, t[c++] = a + 5;
    }
  CHECK(isoform_mesh_from_arrays_f64(p, 25, t, 32, &m) == ISOFORM_OK);
  if (!m) return;
  isoform_curvature_options_default(&o);
  CHECK(isoform_curvature(m, &o, NULL) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_curvature(m, ISOFORM_CURVATURE_MEAN, h) == ISOFORM_OK);
  for (i = 0; i < 25; ++i) CHECK(fabs(h[i]) < 1e-9);
  isoform_mesh_free(m);
}

/* Normals set by the caller frame and orient the fit: the sphere's normals
 * turned inward and doubled in length come back unit and inward, and the
 * curvature then has H = -1/r. A zero normal is refused, the mesh kept. */
static void test_set_normals(void) {
  isoform_mesh* m = sphere_contour();
  isoform_curvature_options o;
  size_t n, i, negative = 0;
  float *normals, *back, *h;
  double h_err = 0;
  if (!m) return;
  n = isoform_mesh_vertex_count(m);
  normals = malloc(3 * n * sizeof *normals);
  back = malloc(3 * n * sizeof *back);
  h = malloc(n * sizeof *h);
  CHECK(isoform_mesh_copy_normals(m, normals) == ISOFORM_OK);
  for (i = 0; i < 3 * n; ++i) normals[i] *= -2.0f;
  CHECK(isoform_mesh_set_normals(m, normals) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_normals(m, back) == ISOFORM_OK);
  for (i = 0; i < n; ++i) {
    const float* q = &back[3 * i];
    CHECK(fabs(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] - 1) < 1e-6);
    CHECK(fabs(q[0] - 0.5f * normals[3 * i]) < 1e-6 && fabs(q[2] - 0.5f * normals[3 * i + 2]) < 1e-6);
  }
  isoform_curvature_options_default(&o);
  CHECK(isoform_curvature(m, &o, NULL) == ISOFORM_OK);
  CHECK(isoform_mesh_copy_curvature(m, ISOFORM_CURVATURE_MEAN, h) == ISOFORM_OK);
  for (i = 0; i < n; ++i) {
    h_err += (h[i] + 0.2) * (h[i] + 0.2);
    negative += h[i] < 0;
  }
  CHECK(negative == n);
  CHECK(sqrt(h_err / (double)n) < 0.01);
  normals[3 * 5] = normals[3 * 5 + 1] = normals[3 * 5 + 2] = 0.0f;
  CHECK(isoform_mesh_set_normals(m, normals) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(strstr(isoform_last_error(), "normal 5 ") != NULL);
  CHECK(isoform_mesh_copy_normals(m, normals) == ISOFORM_OK);
  CHECK(memcmp(normals, back, 3 * n * sizeof *normals) == 0);
  CHECK(isoform_mesh_set_normals(m, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(isoform_mesh_set_normals(NULL, normals) == ISOFORM_ERR_INVALID_ARGUMENT);
  free(normals), free(back), free(h);
  isoform_mesh_free(m);
}

int main(void) {
  test_options_default();
  test_sphere();
  test_cancel_and_errors();
  test_plane_f64();
  test_set_normals();
  if (check_failures) fprintf(stderr, "%d checks failed\n", check_failures);
  return check_failures ? 1 : 0;
}
