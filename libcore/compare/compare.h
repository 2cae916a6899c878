// The comparison study's measuring pass: every surface is sampled at the
// same barycentric lattice of every base triangle, its edges at the same
// points from both sides, and its tessellation is made from the lattice.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "libcore/mesh.h"
#include "libcore/progress.h"
#include "libcore/surface.h"
#include "metrics.h"
#include "reference.h"

namespace isoform::compare {

struct CompareSettings {
  // Lattice (u, v) = (i/k, j/k), i + j <= k: (k+1)(k+2)/2 samples per base
  // triangle, k^2 triangles of the tessellation, k samples per edge at
  // fractions (j + 1/2) / k. 1..64.
  int level = 8;
  // Triangles whose lattice samples enter the sample table (evenly spaced
  // through the triangle table; all when there are fewer). 0 = none.
  long long table_triangles = 2000;
};

struct NamedSurface {
  std::string name;
  const TriangleSurface* surface = nullptr;
};

// One lattice sample of the sample table, and what each surface gave there.
struct SampleRow {
  int32_t triangle = 0;
  double u = 0.0, v = 0.0;
};
struct SampleValues {
  double x = 0.0, y = 0.0, z = 0.0;
  double deviation = 0.0;  // NaN without a reference
  double mean = 0.0, gauss = 0.0;
};

struct CompareResult {
  long long base_vertices = 0, base_triangles = 0;
  int level = 0;
  std::string reference_kind = "none", reference_description, deviation_unit;
  std::vector<SurfaceMetrics> surfaces;
  std::vector<Mesh> tessellations;               // one per surface, same order
  std::vector<SampleRow> rows;                   // the sample table's samples
  std::vector<std::vector<SampleValues>> values; // [surface][row]
  std::vector<std::string> notes;                // what was left out, and why
};

// Measures every surface over base (which needs its neighbour table;
// compute_neighbours). reference may be null. One thread, so the times are
// comparable. Throws InvalidArgument for a bad level, Cancelled when asked.
CompareResult compare_surfaces(const Mesh& base, const std::vector<NamedSurface>& surfaces,
                               const Reference* reference, const CompareSettings& settings,
                               const Progress& progress);

}  // namespace isoform::compare
