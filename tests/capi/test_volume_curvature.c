/* The C API's curvature of trivariate graphs as a C caller sees it: results
 * at exactly the active voxels (zero curvature included) after a write and a
 * read back, stats, and refusals.
 *
 * usage: test_volume_curvature sparse|refusals DIR
 * (smoke.vdb is covered through the CLI, tests/cli/test_cli_curvature_volume.py.) */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"

static const char* const kGrids[5] = {"mean", "gauss", "k1", "k2", "k3"};

/* A 24^3 array, 0 (the background) outside a ball of radius 8 and inside
 * value_inside(x): once written, the VDB's active voxels are the ball. */
static float constant_one(int i, int j, int k) { (void)i; (void)j; (void)k; return 1.0f; }
static float paraboloid(int i, int j, int k) { return 1.0f + 0.01f * (float)(i * i + j * j + k * k); }

static void make_ball(const char* path, float (*value_inside)(int, int, int), long long* active) {
  static float v[24 * 24 * 24];
  const double spacing[3] = {0.5, 0.5, 0.5}, origin[3] = {-6, -6, -6};
  isoform_volume* dense = NULL;
  int i, j, k;
  *active = 0;
  for (k = 0; k < 24; ++k)
    for (j = 0; j < 24; ++j)
      for (i = 0; i < 24; ++i) {
        const int in = (i - 12) * (i - 12) + (j - 12) * (j - 12) + (k - 12) * (k - 12) <= 64;
        v[(k * 24 + j) * 24 + i] = in ? value_inside(i - 12, j - 12, k - 12) : 0.0f;
        *active += in;
      }
  CHECK(isoform_volume_from_dense(v, 24, 24, 24, spacing, origin, "f", ISOFORM_CLASS_FOG, &dense) == ISOFORM_OK);
  CHECK(isoform_volume_save_vdb(dense, path) == ISOFORM_OK);
  isoform_volume_free(dense);
}

/* Opens path and checks it holds the five result grids with `active` voxels each. */
static void expect_result_file(const char* path, long long active) {
  isoform_volume* back = NULL;
  int g;
  CHECK(isoform_volume_open(path, &back) == ISOFORM_OK);
  if (!back) return;
  CHECK(isoform_volume_grid_count(back) == 5);
  for (g = 0; g < 5; ++g) {
    isoform_grid_info info;
    const int index = isoform_volume_find_grid(back, kGrids[g]);
    CHECK(index >= 0);
    if (index < 0) continue;
    CHECK(isoform_volume_grid_info(back, index, &info) == ISOFORM_OK);
    CHECK(info.active_voxels == active);
    CHECK(info.grid_class == ISOFORM_CLASS_OTHER);
    CHECK(info.is_scalar);
  }
  isoform_volume_free(back);
}

static isoform_volume* curvature_of(const char* path, int method, isoform_volume_curvature_stats* stats) {
  isoform_volume *in = NULL, *out = NULL;
  isoform_volume_curvature_options o;
  CHECK(isoform_volume_open(path, &in) == ISOFORM_OK);
  if (!in) return NULL;
  isoform_volume_curvature_options_default(&o);
  CHECK(o.method == ISOFORM_VOLUME_CURVATURE_DEFAULT && o.threads == 0);
  o.method = method;
  CHECK(isoform_volume_curvature(in, isoform_volume_find_grid(in, NULL), &o, NULL, &out) == ISOFORM_OK);
  isoform_volume_free(in);
  if (out) CHECK(isoform_volume_curvature_stats_get(out, stats) == ISOFORM_OK);
  return out;
}

static long long fit_total(const isoform_volume_curvature_stats* s) {
  long long n = 0;
  int f;
  for (f = 0; f < ISOFORM_GRAPH_FIT_COUNT; ++f) n += s->fits[f];
  return n;
}

static void case_sparse(const char* dir) {
  char in[1024], out[1024];
  long long active = 0;
  int method;
  snprintf(in, sizeof in, "%s/ball.vdb", dir);
  snprintf(out, sizeof out, "%s/ball-curvature.vdb", dir);
  /* Constant inside: every curvature is exactly 0, the background, and must
   * still be written as active. */
  make_ball(in, constant_one, &active);
  for (method = 0; method < 2; ++method) {
    isoform_volume_curvature_stats s;
    isoform_volume* r = curvature_of(in, method, &s);
    if (!r) continue;
    CHECK(s.points == active && fit_total(&s) == active);
    CHECK(s.method == method);
    CHECK(s.grids[0].min == 0.0 && s.grids[0].max == 0.0);
    CHECK(s.fits[ISOFORM_GRAPH_FIT_NONE] == 6);
    CHECK(isoform_volume_save_vdb(r, out) == ISOFORM_OK);
    expect_result_file(out, active);
    isoform_volume_free(r);
    unlink(out);
  }
  /* A paraboloid: mean curvature positive, largest at the centre where the
   * gradient vanishes: k = 2 * 0.01 / 0.25 = 0.08 per axis. The ball's 6
   * poles have no 3 voxels in a row across and only 4 platelet points: no
   * fit, results 0. */
  make_ball(in, paraboloid, &active);
  {
    isoform_volume_curvature_stats s;
    isoform_volume* r = curvature_of(in, ISOFORM_VOLUME_CURVATURE_DEFAULT, &s);
    if (r) {
      CHECK(s.points == active);
      CHECK(s.fits[ISOFORM_GRAPH_FIT_NONE] == 6);
      CHECK(s.grids[0].min == 0.0 && s.grids[0].p01 > 0.0);
      CHECK(fabs(s.grids[0].max - 0.08) < 1e-4);
      CHECK(s.grids[2].p50 >= s.grids[3].p50 && s.grids[3].p50 >= s.grids[4].p50);
      CHECK(isoform_volume_save_vdb(r, out) == ISOFORM_OK);
      expect_result_file(out, active);
      /* The result remembers its input: saving over it is refused. */
      CHECK(isoform_volume_save_vdb(r, in) == ISOFORM_ERR_INVALID_ARGUMENT);
      isoform_volume_free(r);
    }
  }
  unlink(in);
  unlink(out);
}

static void case_refusals(void) {
  isoform_volume *v = NULL, *out = (isoform_volume*)1;
  isoform_volume_curvature_options o;
  isoform_volume_curvature_stats s;
  const float values[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  CHECK(isoform_volume_from_dense(values, 2, 2, 2, NULL, NULL, NULL, ISOFORM_CLASS_FOG, &v) == ISOFORM_OK);
  CHECK(isoform_volume_curvature(v, 3, NULL, NULL, &out) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(out == NULL);
  CHECK(strstr(isoform_last_error(), "out of range") != NULL);
  isoform_volume_curvature_options_default(&o);
  o.method = 7;
  CHECK(isoform_volume_curvature(v, 0, &o, NULL, &out) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(isoform_volume_curvature(NULL, 0, NULL, NULL, &out) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(isoform_volume_curvature_stats_get(v, &s) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(strstr(isoform_last_error(), "not a curvature result") != NULL);
  /* 2^3 samples: no point has 3 in a row, so the default's box fit fails
   * everywhere. The seed's platelet, its fallback, has 6 points inside the
   * cell (enough for its 6 unknowns) only at the two ends of the split's cell
   * diagonal, (1,0,0) and (0,1,1); the other 6 points get no fit, results 0.
   * f is linear, so every result is 0. */
  CHECK(isoform_volume_curvature(v, 0, NULL, NULL, &out) == ISOFORM_OK);
  if (out) {
    CHECK(isoform_volume_curvature_stats_get(out, &s) == ISOFORM_OK);
    CHECK(s.points == 8 && s.fits[ISOFORM_GRAPH_FIT_PLATELET_PARTIAL] == 2 && s.fits[ISOFORM_GRAPH_FIT_NONE] == 6);
    CHECK(fabs(s.grids[0].min) < 1e-6 && fabs(s.grids[0].max) < 1e-6);
  }
  CHECK(strcmp(isoform_graph_fit_name(99), "unknown") == 0);
  {
    /* A cancel flag set before the call: ISOFORM_ERR_CANCELLED, no result. */
    isoform_progress progress = {0.0f, 0, 1};
    isoform_volume* cancelled = (isoform_volume*)1;
    CHECK(isoform_volume_curvature(v, 0, NULL, &progress, &cancelled) == ISOFORM_ERR_CANCELLED);
    CHECK(cancelled == NULL);
  }
  isoform_volume_free(out);
  isoform_volume_free(v);
}

int main(int argc, char** argv) {
  const char* which = argc > 1 ? argv[1] : "";
  const char* dir = argc > 2 ? argv[2] : "/tmp";
  mkdir(dir, 0755);
  if (!strcmp(which, "sparse")) case_sparse(dir);
  else if (!strcmp(which, "refusals")) case_refusals();
  else {
    fprintf(stderr, "usage: test_volume_curvature sparse|refusals DIR\n");
    return 2;
  }
  if (check_failures) fprintf(stderr, "%d checks failed\n", check_failures);
  return check_failures ? 1 : 0;
}
