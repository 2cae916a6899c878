// Surfaces whose curvature is known exactly, as test meshes: the nine graphs
// of Table 4.1 of Hamann (1991) on the seed's 51 x 51 grid, and a sphere, a
// torus and an ellipsoid as regular or jittered triangulations. Exact values
// use isoform's sign (positive where the surface bends away from its normal;
// graphs have the upward normal, closed surfaces the outward one).
#pragma once

#include <string>
#include <vector>

#include "libcore/mesh.h"

namespace isoform::truth {

struct Exact {
  double k1 = 0, k2 = 0;  // k1 >= k2
  double mean() const { return 0.5 * (k1 + k2); }
  double gauss() const { return k1 * k2; }
};

// A bivariate function with first and second derivatives.
struct Graph {
  std::string name, formula;
  double (*f)(double x, double y);
  void (*derivatives)(double x, double y, double d[5]);  // fx fy fxx fxy fyy
  double seed_rms[4];  // the seed's Table 4.1 row: k1, k2, H, K
};

// The nine functions of Table 4.1 (function 7 with .15: the table prints
// 15(x^3 + 2x^2y - xy + 2y^2), but the captions of Figures 4.5, 4.6 and 5.8
// print .15(...); the decimal point was lost in the table).
const std::vector<Graph>& table41_graphs();

// Exact principal curvatures of z = f(x, y) with the upward normal.
Exact graph_curvature(const Graph& g, double x, double y);

// The seed's triangulation of the graph over [-1, 1]^2 with n x n points:
// vertex (i, j) at index j * n + i, each quad split into
// ((i,j),(i+1,j),(i+1,j+1)) and ((i,j),(i+1,j+1),(i,j+1)). No normals.
Mesh graph_mesh(const Graph& g, int n = 51);

enum class Shape { Sphere, Torus, Ellipsoid };
const char* shape_name(Shape s);

// A closed triangulation of the shape with about `resolution` points around
// its longest circle; jitter moves each point along the surface by up to
// that fraction of the local edge length (deterministic for a seed). The
// exact curvature of each vertex goes into exact. No normals.
Mesh shape_mesh(Shape s, int resolution, double jitter, unsigned seed, std::vector<Exact>& exact);

// Exact outward unit normals of the shape's mesh vertices.
std::vector<float> shape_normals(Shape s, const Mesh& mesh);

struct Rms {
  double k1 = 0, k2 = 0, mean = 0, gauss = 0;
};
// RMS (4.32) of the mesh's curvature against exact, over the vertices where
// include[v] is true (all when include is empty).
Rms rms_error(const Mesh& mesh, const std::vector<Exact>& exact, const std::vector<bool>& include = {});

}  // namespace isoform::truth

namespace isoform::truth {

// One row of Table 4.1 for a method: the graph's mesh, normals estimated
// from the mesh alone (Remark 3.15), curvature, and the RMS over all
// vertices and over interior ones.
struct Table41Row {
  Rms all, interior;
};
Table41Row table41_row(const Graph& g, CurvatureMethod method, int n = 51);

}  // namespace isoform::truth
