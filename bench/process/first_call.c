/* What a host such as the Blender add-on pays for its first contour in a
 * fresh process, beside a second, warm call: opening the file, then two
 * contours of the same grid, each to a mesh that is freed at once.
 *
 * usage: first_call IN.vdb ISOVALUE
 * prints one JSON object: open_ms, first_ms, second_ms, triangles */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "isoform.h"

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static int fail(const char* what) {
  fprintf(stderr, "first_call: %s: %s\n", what, isoform_last_error());
  return 1;
}

int main(int argc, char** argv) {
  isoform_volume* volume = NULL;
  isoform_contour_options options;
  double start, ms[3];
  size_t triangles = 0;
  int call;
  if (argc != 3) {
    fprintf(stderr, "usage: first_call IN.vdb ISOVALUE\n");
    return 2;
  }
  start = now_ms();
  if (isoform_volume_open(argv[1], &volume) != ISOFORM_OK) return fail("open");
  ms[0] = now_ms() - start;
  isoform_contour_options_default(&options);
  options.auto_isovalue = 0;
  options.isovalue = atof(argv[2]);
  for (call = 1; call <= 2; ++call) {
    isoform_mesh* mesh = NULL;
    start = now_ms();
    if (isoform_contour(volume, isoform_volume_find_grid(volume, NULL), &options, NULL, &mesh) != ISOFORM_OK)
      return fail("contour");
    triangles = isoform_mesh_triangle_count(mesh);
    isoform_mesh_free(mesh);
    ms[call] = now_ms() - start;
  }
  isoform_volume_free(volume);
  printf("{\"open_ms\": %.3f, \"first_ms\": %.3f, \"second_ms\": %.3f, \"triangles\": %zu}\n", ms[0], ms[1], ms[2],
         triangles);
  return 0;
}
