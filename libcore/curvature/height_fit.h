// The height-field fits of Section 4.2 of Hamann (1991): platelet points in
// a vertex's local frame (u, v along the tangent plane, d along the normal),
// and a bivariate polynomial d = f(u, v) through the origin fitted to them by
// least squares (4.28, 4.29). The seed's fit has only the three quadratic
// terms, so it trusts the normal completely; the other models add the linear
// terms, which absorb an error in the normal, and cubic or quartic terms,
// which keep the third and fourth order of the surface out of the second
// derivatives.
#pragma once

namespace isoform {

enum class FitModel {
  SeedQuadratic,  // 1/2 (c20 u^2 + 2 c11 u v + c02 v^2): (4.28), 3 terms
  Quadric,        // linear and quadratic terms: 5
  Cubic,          // up to degree 3: 9
  Quartic         // up to degree 4: 14
};

// Number of coefficients of a model.
int fit_terms(FitModel model);

// The derivatives of the fitted height field at the origin.
struct HeightFit {
  bool ok = false;
  double fu = 0, fv = 0, fuu = 0, fuv = 0, fvv = 0;
  double rcond = 0;  // smallest over largest pivot of the scaled normal equations
};

// Fits `model` to the points (u[j], v[j], d[j]), j < count. Coordinates are
// scaled by the largest |(u, v)| before the normal equations are formed, so
// the conditioning check is independent of the mesh's size. Fails (ok false)
// with fewer points than terms or when rcond falls below min_rcond.
HeightFit fit_height(FitModel model, const double* u, const double* v, const double* d, int count,
                     double min_rcond = 1e-10);

// fit_height on four point sets at once, side by side: point j of set l at
// u[4 j + l], v[4 j + l], d[4 j + l], count[l] points in set l (0 for an
// unused lane), every set padded with zeros up to the longest. out[l] is
// what fit_height gives for set l alone, bit for bit, and faster for the
// larger models (the sums and factorisations run in the lanes of a vector).
void fit_height_lanes(FitModel model, const double* u, const double* v, const double* d, const int (&count)[4],
                      HeightFit (&out)[4], double min_rcond = 1e-10);

// Four point sets in fit_height_lanes' layout.
struct LaneGroup {
  const double *u, *v, *d;
  int count[4];
};

// fit_height_lanes on two groups of four sets, every set padded with zeros
// up to the longest of all eight: out[g][l] is what fit_height gives for set
// l of group g alone, bit for bit. With AVX-512 the eight sets run in the
// lanes of one vector (one pass of the arithmetic where two groups one
// after another take two).
void fit_height_lanes(FitModel model, const LaneGroup (&groups)[2], HeightFit (&out)[2][4],
                      double min_rcond = 1e-10);

}  // namespace isoform
