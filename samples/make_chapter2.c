/* The seed's Chapter 2 examples as VDB files, made through the C API:
 *   gaussians.vdb: f = 15 (e^{-0.005 |x - (10,10,10)|^2} + e^{-0.0025 |x - (15,20,20)|^2}
 *                  + e^{-0.005 |x - (25,25,25)|^2}) sampled at the integers of [0, 39]^3
 *                  (Figures 2.2, 2.3, 2.9);
 *   ball.vdb:      f = cos(2 |x|) on [-1, 1]^3, 41 samples per axis (Figure 2.4).
 * usage: isoform_make_chapter2 OUTPUT_FOLDER */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "isoform.h"

static double gaussians(double x, double y, double z) {
  const double a = (x - 10) * (x - 10) + (y - 10) * (y - 10) + (z - 10) * (z - 10);
  const double b = (x - 15) * (x - 15) + (y - 20) * (y - 20) + (z - 20) * (z - 20);
  const double c = (x - 25) * (x - 25) + (y - 25) * (y - 25) + (z - 25) * (z - 25);
  return 15.0 * (exp(-0.005 * a) + exp(-0.0025 * b) + exp(-0.005 * c));
}

static double ball(double x, double y, double z) { return cos(2.0 * sqrt(x * x + y * y + z * z)); }

/* Samples f at origin + spacing * (i, j, k), i, j, k < n, and saves it. */
static int save(const char* folder, const char* name, int n, double spacing, double origin,
                double (*f)(double, double, double)) {
  const double s[3] = {spacing, spacing, spacing}, o[3] = {origin, origin, origin};
  float* values = malloc(sizeof(float) * (size_t)n * n * n);
  isoform_volume* volume = NULL;
  char path[4096];
  int i, j, k, ok;
  if (!values) return 0;
  for (k = 0; k < n; ++k)
    for (j = 0; j < n; ++j)
      for (i = 0; i < n; ++i)
        values[((size_t)k * n + j) * n + i] = (float)f(origin + spacing * i, origin + spacing * j, origin + spacing * k);
  snprintf(path, sizeof path, "%s/%s.vdb", folder, name);
  ok = isoform_volume_from_dense(values, n, n, n, s, o, name, ISOFORM_CLASS_OTHER, &volume) == ISOFORM_OK &&
       isoform_volume_save_vdb(volume, path) == ISOFORM_OK;
  if (!ok) fprintf(stderr, "isoform_make_chapter2: error: %s\n", isoform_last_error());
  else printf("wrote %s\n", path);
  isoform_volume_free(volume);
  free(values);
  return ok;
}

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: %s OUTPUT_FOLDER\n", argv[0]);
    return 2;
  }
  if (!save(argv[1], "gaussians", 40, 1.0, 0.0, gaussians)) return 1;
  if (!save(argv[1], "ball", 41, 0.05, -1.0, ball)) return 1;
  return 0;
}
