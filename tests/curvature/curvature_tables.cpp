// Writes docs/curvature-surface.md: Table 4.1 of Hamann (1991) with the
// seed's values beside isoform's, and the convergence study on a sphere, a
// torus and an ellipsoid. Usage: curvature_tables OUT.md
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "libcore/curvature/surface_curvature.h"
#include "libcore/mesh_normals.h"
#include "../core/mesh_checks.h"
#include "truth.h"

using namespace isoform;
using namespace isoform::truth;

namespace {

const CurvatureMethod kMethods[] = {CurvatureMethod::Seed, CurvatureMethod::Quadric, CurvatureMethod::Cubic,
                                    CurvatureMethod::Quartic};

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, x == 0 ? "0" : (x < 1e-3 ? "%.1e" : "%.6f"), x);
  return buf;
}

void table41(std::ostream& out, CurvatureMethod method, bool interior) {
  out << "\n### " << curvature_method_name(method) << ", RMS over " << (interior ? "interior" : "all 51·51")
      << " vertices\n\n| function | k1 | seed k1 | k2 | seed k2 | H | seed H | K | seed K |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Graph& g : table41_graphs()) {
    const Table41Row row = table41_row(g, method);
    const Rms& r = interior ? row.interior : row.all;
    const double v[4] = {r.k1, r.k2, r.mean, r.gauss};
    out << "| " << g.name << " `" << g.formula << "` |";
    for (int q = 0; q < 4; ++q) out << " " << num(v[q]) << " | " << num(g.seed_rms[q]) << " |";
    out << "\n";
  }
}

void convergence(std::ostream& out, Shape shape, double jitter) {
  out << "\n### " << shape_name(shape) << (jitter > 0 ? ", jittered" : ", regular")
      << ": RMS of H (and K) by resolution, normals from the mesh\n\n| method |";
  const int res[3] = {32, 64, 128};
  for (int r : res) out << " " << r << " |";
  out << " order |\n|---|---:|---:|---:|---:|\n";
  for (CurvatureMethod method : kMethods) {
    double err[3];
    out << "| " << curvature_method_name(method) << " |";
    for (int i = 0; i < 3; ++i) {
      std::vector<Exact> exact;
      Mesh m = shape_mesh(shape, res[i], jitter, 7, exact);
      estimate_normals(m);
      CurvatureOptions options;
      options.method = method;
      compute_curvature(m, options, Progress(nullptr));
      const Rms e = rms_error(m, exact);
      err[i] = e.mean;
      out << " " << num(e.mean) << " (" << num(e.gauss) << ") |";
    }
    out << " " << num(std::log2(err[1] / err[2])) << " |\n";
  }
}

// Contours of level-set spheres (Chapter 3, Zucker-Hummel normals): the RMS
// of H relative to 1/r, per method.
void contour_spheres(std::ostream& out) {
  out << "\n### Contours of level-set spheres: RMS of H relative to 1/r\n\n"
      << "A dense signed-distance field of a sphere of radius r voxels (centre off the grid), contoured\n"
      << "by the cell method; normals from the volume's gradient. The contour's vertices carry the\n"
      << "interpolation error of Chapter 3, so higher orders gain less here than on exact surfaces.\n\n"
      << "| method | r = 6 | r = 12 | r = 24 |\n|---|---:|---:|---:|\n";
  for (CurvatureMethod method : kMethods) {
    out << "| " << curvature_method_name(method) << " |";
    for (double r : {6.0, 12.0, 24.0}) {
      const int n = int(2 * r + 8);
      const double c = n / 2.0 - 0.5;
      auto grid = test::dense_grid({n, n, n}, [&](int x, int y, int z) {
        return std::sqrt((x - c) * (x - c) + (y - c - 0.2) * (y - c - 0.2) + (z - c + 0.2) * (z - c + 0.2)) - r;
      }, GridClass::LevelSet);
      Mesh m = test::run_contour(*grid, 0.0);
      CurvatureOptions options;
      options.method = method;
      compute_curvature(m, options, Progress(nullptr));
      double h2 = 0;
      for (size_t v = 0; v < m.vertex_count(); ++v) h2 += std::pow(m.curvature.mean[v] - 1 / r, 2);
      out << " " << num(std::sqrt(h2 / double(m.vertex_count())) * r) << " |";
    }
    out << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {
    std::cerr << "usage: curvature_tables [DOC.md]   (writes the document there, or to standard output)\n";
    return 2;
  }
  std::ostringstream out;
  out << "# Surface curvature: Table 4.1 and convergence\n\n"
      << "Written by `build/tests/curvature/curvature_tables docs/curvature-surface.md` (the numbers are\n"
      << "computed when the tool runs; `tests/curvature/test_surface_curvature.cpp` guards them).\n\n"
      << "## Protocol\n\n"
      << "- Table 4.1: the seed's nine functions on its 51 x 51 grid over [-1, 1]^2, each quad split into\n"
      << "  ((i,j),(i+1,j),(i+1,j+1)) and ((i,j),(i+1,j+1),(i,j+1)); points in double precision (as the\n"
      << "  seed computed; float coordinates alone put a floor of about 1e-5 under every entry at this\n"
      << "  spacing); normals estimated from the mesh alone (Remark 3.15, `estimate_normals`), never the\n"
      << "  exact ones; RMS (4.32) over all 51·51 vertices, and over the interior ones. Function 7 uses\n"
      << "  .15: Table 4.1 prints `15(x^3 + 2x^2y - xy + 2y^2)`, but the captions of Figures 4.5, 4.6\n"
      << "  and 5.8 print `.15(...)`; the decimal point was lost in the table.\n"
      << "- Sign: isoform's curvature is positive where the surface bends away from its normal (graphs:\n"
      << "  the upward normal); the seed's (4.31) has the opposite sign. H and K errors do not depend on\n"
      << "  the sign; k1 >= k2 in isoform's sign, so the seed's k1 and k2 columns may be swapped\n"
      << "  relative to ours (the seed does not say how it ordered them).\n"
      << "- Methods: `seed` is (4.28)-(4.31) as printed: three quadratic terms over the one-ring, with\n"
      << "  the normal as given and no boundary treatment. `quadric` adds the linear terms (one-ring),\n"
      << "  `cubic` fits up to cubic terms over the two-ring, `quartic` (the default) up to quartic\n"
      << "  terms over the three-ring. Boundary vertices take rings enough for one-sided fits (2, 3, 4\n"
      << "  and 5 rings). Where a fit is short of points or badly conditioned the platelet widens,\n"
      << "  then the order drops, and the vertex is flagged.\n"
      << "- Convergence: a unit sphere and an ellipsoid (semi-axes 1, 0.7, 0.5) as equal-angle cube\n"
      << "  spheres, a torus (R = 1, r = 0.4) as a (u, v) grid; jittered meshes move every point along\n"
      << "  the surface by up to 1/4 of the grid step; resolution = points around the longest circle;\n"
      << "  normals estimated from the mesh; order = log2 of the error ratio from 64 to 128.\n";
  for (CurvatureMethod m : kMethods) table41(out, m, false);
  for (CurvatureMethod m : kMethods) table41(out, m, true);
  for (Shape s : {Shape::Sphere, Shape::Torus, Shape::Ellipsoid})
    for (double j : {0.0, 0.25}) convergence(out, s, j);
  contour_spheres(out);
  if (argc < 2) {
    std::cout << out.str();
    return 0;
  }
  std::ofstream file(argv[1]);
  file << out.str();
  if (!file) std::cerr << argv[1] << ": cannot write\n";
  return file ? 0 : 1;
}
