/* The trivariate graphs of Figures 4.9 to 4.12 as VDB files, made through the
 * C API on the seed's 26^3 grid over [-1, 1]^3 (spacing 0.08):
 *   figure49.vdb:  .4(x^2 + y^2 + z^2)
 *   figure410.vdb: .4(x^2 - y^2 - z^2)
 *   figure411.vdb: .15(x^3 + 2x^2 y - x z^2 + 2y^2)
 *   figure412.vdb: .1(cos(pi x) + cos(pi y) + cos(pi z))
 * Each is stored as f + 1: a constant changes no curvature of the graph, and
 * it keeps every sample off the VDB background 0, so every voxel is active.
 * `isoform curvature-volume` then `isoform slice --grid mean --map diverging`
 * give the pictures (samples/curvature_slices.sh).
 * usage: isoform_make_chapter4 OUTPUT_FOLDER */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "isoform.h"

static const double kPi = 3.14159265358979323846;

static double f49(double x, double y, double z) { return 0.4 * (x * x + y * y + z * z); }
static double f410(double x, double y, double z) { return 0.4 * (x * x - y * y - z * z); }
static double f411(double x, double y, double z) { return 0.15 * (x * x * x + 2 * x * x * y - x * z * z + 2 * y * y); }
static double f412(double x, double y, double z) { return 0.1 * (cos(kPi * x) + cos(kPi * y) + cos(kPi * z)); }

static int save(const char* folder, const char* name, double (*f)(double, double, double)) {
  enum { n = 26 };
  const double s[3] = {0.08, 0.08, 0.08}, o[3] = {-1, -1, -1};
  static float values[n * n * n];
  isoform_volume* volume = NULL;
  char path[4096];
  int i, j, k, ok;
  for (k = 0; k < n; ++k)
    for (j = 0; j < n; ++j)
      for (i = 0; i < n; ++i)
        values[(k * n + j) * n + i] = (float)(1.0 + f(-1 + 0.08 * i, -1 + 0.08 * j, -1 + 0.08 * k));
  snprintf(path, sizeof path, "%s/%s.vdb", folder, name);
  ok = isoform_volume_from_dense(values, n, n, n, s, o, "f", ISOFORM_CLASS_OTHER, &volume) == ISOFORM_OK &&
       isoform_volume_save_vdb(volume, path) == ISOFORM_OK;
  if (!ok) fprintf(stderr, "isoform_make_chapter4: error: %s\n", isoform_last_error());
  else printf("wrote %s\n", path);
  isoform_volume_free(volume);
  return ok;
}

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: %s OUTPUT_FOLDER\n", argv[0]);
    return 2;
  }
  return save(argv[1], "figure49", f49) && save(argv[1], "figure410", f410) && save(argv[1], "figure411", f411) &&
                 save(argv[1], "figure412", f412)
             ? 0
             : 1;
}
