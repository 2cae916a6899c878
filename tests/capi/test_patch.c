/* The side-vertex surface calls of isoform.h from C: options, Figure 6.7's
 * tetrahedron, evaluation, a watertight tessellation, progress, and bad
 * input (missing normals, bad samples, bad options). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "isoform.h"

/* A regular tetrahedron in the unit sphere with the sphere's normals. */
static isoform_mesh* tetrahedron(void) {
  const float s = (float)(1.0 / sqrt(3.0));
  const float p[12] = {s, s, s, s, -s, -s, -s, s, -s, -s, -s, s};
  const int32_t t[12] = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
  isoform_mesh* m = NULL;
  CHECK(isoform_mesh_from_arrays(p, 4, t, 4, &m) == ISOFORM_OK);
  CHECK(isoform_mesh_normals_estimated(m) == 1);
  CHECK(isoform_mesh_set_normals(m, p) == ISOFORM_OK);
  CHECK(isoform_mesh_normals_estimated(m) == 0);
  return m;
}

static void test_options_default(void) {
  isoform_patch_options o;
  memset(&o, 0x7f, sizeof o);
  isoform_patch_options_default(&o);
  CHECK(o.blend == ISOFORM_PATCH_BLEND_SQUARED);
  CHECK(o.tension == 0.0 && o.edge_tension_count == 0);
  CHECK(o.edge_tension_vertices == NULL && o.edge_tension_values == NULL);
}

static void test_tetrahedron(void) {
  isoform_mesh* m = tetrahedron();
  isoform_patch* patch = NULL;
  isoform_patch_stats st;
  isoform_mesh* out = NULL;
  isoform_mesh_stats ms;
  isoform_progress progress;
  const int32_t tri[4] = {0, 0, 1, 3};
  const double uv[8] = {0.5, 0.0, 1.0 / 3, 1.0 / 3, 0.0, 0.0, 0.25, 0.5};
  double points[12], normals[12];
  int k;
  CHECK(isoform_patch_create(m, NULL, &patch) == ISOFORM_OK);
  isoform_mesh_free(m); /* the patch keeps its own copy */
  CHECK(isoform_patch_stats_get(patch, &st) == ISOFORM_OK);
  CHECK(st.triangles == 4 && st.edges == 6 && st.nonconvex_edges == 0 && st.opposite_normal_edges == 0);
  CHECK(isoform_patch_evaluate(patch, 4, tri, uv, points, normals) == ISOFORM_OK);
  /* An edge midpoint is on the sphere (great arc); the face centre inside. */
  CHECK(fabs(sqrt(points[0] * points[0] + points[1] * points[1] + points[2] * points[2]) - 1) < 1e-6);
  CHECK(sqrt(points[3] * points[3] + points[4] * points[4] + points[5] * points[5]) < 0.99);
  /* Vertex 0 of triangle 1 with its normal (float input: 1e-6). */
  CHECK(fabs(points[6] - 1 / sqrt(3.0)) < 1e-6 && fabs(normals[8] - 1 / sqrt(3.0)) < 1e-6);
  for (k = 0; k < 12; ++k) CHECK(isfinite(points[k]) && isfinite(normals[k]));
  /* Normals point outward like the triangles' winding. */
  for (k = 0; k < 4; ++k)
    CHECK(points[3 * k] * normals[3 * k] + points[3 * k + 1] * normals[3 * k + 1] + points[3 * k + 2] * normals[3 * k + 2] > 0);
  memset(&progress, 0, sizeof progress);
  CHECK(isoform_patch_tessellate(patch, 3, &progress, &out) == ISOFORM_OK);
  CHECK(progress.stage == ISOFORM_STAGE_DONE);
  CHECK(isoform_mesh_stats_get(out, &ms) == ISOFORM_OK);
  CHECK(ms.triangles == 4 * 64 && ms.vertices == 4 + 6 * 7 + 4 * 21);
  CHECK(ms.boundary_edges == 0 && ms.nonmanifold_edges == 0 && ms.inconsistent_edges == 0);
  CHECK(ms.euler_characteristic == 2);
  isoform_mesh_free(out);
  /* Cancel leaves no result. */
  out = NULL;
  progress.cancel = 1;
  CHECK(isoform_patch_tessellate(patch, 3, &progress, &out) == ISOFORM_ERR_CANCELLED && out == NULL);
  /* Bad samples are named. */
  {
    const int32_t bad_t[1] = {4};
    const double bad_uv[2] = {0.7, 0.6};
    CHECK(isoform_patch_evaluate(patch, 1, bad_t, uv, points, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
    CHECK(strstr(isoform_last_error(), "no such triangle") != NULL);
    CHECK(isoform_patch_evaluate(patch, 1, tri, bad_uv, points, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
    CHECK(strstr(isoform_last_error(), "outside the triangle") != NULL);
  }
  CHECK(isoform_patch_tessellate(patch, 11, NULL, &out) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(strstr(isoform_last_error(), "level 11") != NULL);
  isoform_patch_free(patch);
}

/* Many samples at once (the parallel path) give what one at a time gives. */
static void test_many_samples(void) {
  isoform_mesh* m = tetrahedron();
  isoform_patch* patch = NULL;
  const size_t n = 5000;
  int32_t* tri = malloc(n * sizeof *tri);
  double* uv = malloc(2 * n * sizeof *uv);
  double* all = malloc(3 * n * sizeof *all);
  double one[3];
  size_t k, mismatches = 0;
  CHECK(isoform_patch_create(m, NULL, &patch) == ISOFORM_OK);
  for (k = 0; k < n; ++k) {
    tri[k] = (int32_t)(k % 4);
    uv[2 * k] = (double)(k % 71) / 71.0 * 0.5;
    uv[2 * k + 1] = (double)(k % 53) / 53.0 * 0.5;
  }
  CHECK(isoform_patch_evaluate(patch, n, tri, uv, all, NULL) == ISOFORM_OK);
  for (k = 0; k < n; k += 7) {
    CHECK(isoform_patch_evaluate(patch, 1, tri + k, uv + 2 * k, one, NULL) == ISOFORM_OK);
    if (one[0] != all[3 * k] || one[1] != all[3 * k + 1] || one[2] != all[3 * k + 2]) ++mismatches;
  }
  CHECK(mismatches == 0);
  /* The first bad sample is the one named. */
  uv[2 * 4000] = 0.9;
  uv[2 * 4000 + 1] = 0.9;
  uv[2 * 4500] = -1;
  CHECK(isoform_patch_evaluate(patch, n, tri, uv, all, NULL) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(strstr(isoform_last_error(), "sample 4000 ") != NULL);
  free(tri);
  free(uv);
  free(all);
  isoform_patch_free(patch);
  isoform_mesh_free(m);
}

static void test_bad_input(void) {
  isoform_mesh* m = tetrahedron();
  isoform_patch* patch = NULL;
  isoform_patch_options o;
  const int32_t edge[2] = {0, 1};
  const double w = 0.3;
  isoform_patch_options_default(&o);
  o.blend = 7;
  CHECK(isoform_patch_create(m, &o, &patch) == ISOFORM_ERR_INVALID_ARGUMENT && patch == NULL);
  CHECK(strstr(isoform_last_error(), "blend") != NULL);
  isoform_patch_options_default(&o);
  o.tension = -2;
  CHECK(isoform_patch_create(m, &o, &patch) == ISOFORM_ERR_INVALID_ARGUMENT);
  isoform_patch_options_default(&o);
  o.edge_tension_count = 1;
  CHECK(isoform_patch_create(m, &o, &patch) == ISOFORM_ERR_INVALID_ARGUMENT);
  o.edge_tension_vertices = edge;
  o.edge_tension_values = &w;
  CHECK(isoform_patch_create(m, &o, &patch) == ISOFORM_OK);
  isoform_patch_free(patch);
  CHECK(isoform_patch_create(NULL, NULL, &patch) == ISOFORM_ERR_INVALID_ARGUMENT);
  isoform_mesh_free(m);
  isoform_patch_free(NULL);
}

int main(void) {
  test_options_default();
  test_tetrahedron();
  test_many_samples();
  test_bad_input();
  if (check_failures) fprintf(stderr, "%d check(s) failed\n", check_failures);
  return check_failures ? 1 : 0;
}
