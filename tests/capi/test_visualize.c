/* The volume visualisation calls of isoform.h from C: defaults, images with
 * count + copy-out, coloured meshes, and the errors the contract names (no
 * such grid, a position outside the domain, q = 0). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "isoform.h"

/* f = i + 2 j + 3 k on a 5 x 6 x 7 array, spacing 0.5, origin (1, 2, 3). */
static isoform_volume* ramp(void) {
  static float values[5 * 6 * 7];
  const double spacing[3] = {0.5, 0.5, 0.5}, origin[3] = {1, 2, 3};
  isoform_volume* v = NULL;
  int i, j, k;
  for (k = 0; k < 7; ++k)
    for (j = 0; j < 6; ++j)
      for (i = 0; i < 5; ++i) values[(k * 6 + j) * 5 + i] = (float)(i + 2 * j + 3 * k);
  CHECK(isoform_volume_from_dense(values, 5, 6, 7, spacing, origin, "ramp", ISOFORM_CLASS_OTHER, &v) == ISOFORM_OK);
  return v;
}

static void test_defaults(void) {
  isoform_slice_options s;
  isoform_boxes_options b;
  isoform_stack_options t;
  isoform_slice_options_default(&s);
  isoform_boxes_options_default(&b);
  isoform_stack_options_default(&t);
  CHECK(s.position[1] == 0.5 && s.resolution == 256 && s.colour_bar == 1 && s.colour.levels == 256);
  CHECK(b.q[2] == 5 && b.gap[0] == 1.0 && b.colour.map == ISOFORM_MAP_GREEN_WHITE);
  CHECK(fabs(b.uvw_max[2] - 1.5 * 3.14159265358979) < 1e-9);
  CHECK(t.n[0] == 8 && t.transparency == 0.5 && t.view[2] == -1.0);
}

static void test_image(isoform_volume* v) {
  isoform_slice_options o;
  isoform_image* image = NULL;
  int w, h;
  double lo, hi;
  float* values;
  uint8_t* rgba;
  isoform_slice_options_default(&o);
  /* The z slice is x by y (2 by 2.5 world units): 6 samples along y and
   * round(6 * 2 / 2.5) = 5 along x, the grid points. */
  o.resolution = 6;
  o.position[2] = 0.5;
  o.colour_bar = 0;
  CHECK(isoform_slice_image(v, 0, 2, &o, &image) == ISOFORM_OK);
  if (!image) return;
  w = isoform_image_width(image);
  h = isoform_image_height(image);
  CHECK(w == 5 && h == 6);
  values = malloc(sizeof(float) * (size_t)w * h);
  rgba = malloc(4 * (size_t)w * h);
  CHECK(isoform_image_copy_values(image, values) == ISOFORM_OK);
  CHECK(isoform_image_copy_rgba(image, rgba) == ISOFORM_OK);
  /* Row 0 is y = 5 (top), column 0 is x = 0; the plane is k = 3. */
  CHECK(values[0] == 0 + 2 * 5 + 3 * 3);
  CHECK(values[(h - 1) * w + 4] == 4 + 0 + 9);
  CHECK(rgba[3] == 255);
  CHECK(isoform_image_range(image, &lo, &hi) == ISOFORM_OK);
  /* Over all three slices, planes at i = 2, j = 2.5, k = 3: the least value
   * is f(2, 0, 0) on the x slice, the greatest f(2, 5, 6). */
  CHECK(lo == 2.0 && hi == 2 + 10 + 18);
  CHECK(isoform_image_save_png(image, "/nonexistent-folder/x.png") == ISOFORM_ERR_IO);
  CHECK(strstr(isoform_last_error(), "/nonexistent-folder/x.png") != NULL);
  free(values);
  free(rgba);
  isoform_image_free(image);
}

static void test_meshes(isoform_volume* v) {
  isoform_slice_options s;
  isoform_boxes_options b;
  isoform_stack_options t;
  isoform_mesh* m = NULL;
  uint8_t* colours;
  int32_t* edges;
  isoform_slice_options_default(&s);
  s.resolution = 4;
  CHECK(isoform_slice_mesh(v, 0, 3, ISOFORM_SLICE_CURVES, &s, &m) == ISOFORM_OK);
  if (m) {
    CHECK(isoform_mesh_triangle_count(m) == 0 && isoform_mesh_edge_count(m) > 0);
    edges = malloc(sizeof(int32_t) * 2 * isoform_mesh_edge_count(m));
    CHECK(isoform_mesh_copy_edges(m, edges) == ISOFORM_OK);
    CHECK(edges[0] == 0 && edges[1] == 1);
    free(edges);
    isoform_mesh_free(m);
    m = NULL;
  }
  isoform_boxes_options_default(&b);
  b.q[0] = 2;
  b.q[1] = 1;
  b.q[2] = 3;
  CHECK(isoform_boxes(v, 0, &b, &m) == ISOFORM_OK);
  if (m) {
    CHECK(isoform_mesh_triangle_count(m) == 6 * 12);
    CHECK(isoform_mesh_color_count(m) == isoform_mesh_vertex_count(m));
    colours = malloc(4 * isoform_mesh_color_count(m));
    CHECK(isoform_mesh_copy_colors(m, colours) == ISOFORM_OK);
    CHECK(colours[3] == 255);
    free(colours);
    isoform_mesh_free(m);
    m = NULL;
  }
  isoform_stack_options_default(&t);
  t.n[0] = t.n[1] = t.n[2] = 2;
  t.transparency = 0.0;
  CHECK(isoform_stack(v, 0, &t, &m) == ISOFORM_OK);
  if (m) {
    CHECK(isoform_mesh_triangle_count(m) == 2 * 36);
    isoform_mesh_free(m);
  }
}

static void test_errors(isoform_volume* v) {
  isoform_slice_options s;
  isoform_boxes_options b;
  isoform_image* image = NULL;
  isoform_mesh* m = NULL;
  isoform_slice_options_default(&s);
  isoform_boxes_options_default(&b);
  CHECK(isoform_slice_image(v, 3, 0, &s, &image) == ISOFORM_ERR_INVALID_ARGUMENT && image == NULL);
  CHECK(strstr(isoform_last_error(), "no grid 3") != NULL);
  s.position[0] = 1.25;
  CHECK(isoform_slice_image(v, 0, 0, &s, &image) == ISOFORM_ERR_INVALID_ARGUMENT && image == NULL);
  CHECK(strstr(isoform_last_error(), "outside the domain") != NULL);
  s.position[0] = 0.5;
  CHECK(isoform_slice_mesh(v, 0, 4, ISOFORM_SLICE_PLANE, &s, &m) == ISOFORM_ERR_INVALID_ARGUMENT && m == NULL);
  b.q[1] = 0;
  CHECK(isoform_boxes(v, 0, &b, &m) == ISOFORM_ERR_INVALID_ARGUMENT && m == NULL);
  CHECK(strstr(isoform_last_error(), "q = 0") != NULL);
  CHECK(strstr(isoform_last_error(), "'ramp'") != NULL);
  CHECK(isoform_boxes(NULL, 0, &b, &m) == ISOFORM_ERR_INVALID_ARGUMENT);
  CHECK(isoform_stack(v, 0, NULL, &m) == ISOFORM_ERR_INVALID_ARGUMENT);
  isoform_image_free(NULL);
}

int main(void) {
  isoform_volume* v = ramp();
  test_defaults();
  if (v) {
    test_image(v);
    test_meshes(v);
    test_errors(v);
  }
  isoform_volume_free(v);
  if (check_failures) fprintf(stderr, "%d checks failed\n", check_failures);
  return check_failures ? 1 : 0;
}
