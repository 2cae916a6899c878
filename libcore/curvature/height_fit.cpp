// Least-squares height fits in a fixed-size workspace (no heap per vertex).
#include "height_fit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace isoform {
namespace {

constexpr int kMaxTerms = 14;
using Normal = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxTerms, kMaxTerms>;
using Column = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxTerms, 1>;

// The monomials u^i v^j of each model: first the linear ones (when present),
// then degree 2 (u^2, u v, v^2), then higher degrees.
int min_degree(FitModel model) { return model == FitModel::SeedQuadratic ? 2 : 1; }
int max_degree(FitModel model) {
  switch (model) {
    case FitModel::SeedQuadratic:
    case FitModel::Quadric: return 2;
    case FitModel::Cubic: return 3;
    case FitModel::Quartic: return 4;
  }
  return 2;
}

// Fills row with the model's monomials u^(deg-j) v^j at (u, v).
void monomials(FitModel model, double u, double v, double* row) {
  double pu[5] = {1, u, u * u, u * u * u, u * u * u * u};
  double pv[5] = {1, v, v * v, v * v * v, v * v * v * v};
  int n = 0;
  for (int deg = min_degree(model); deg <= max_degree(model); ++deg)
    for (int j = 0; j <= deg; ++j) row[n++] = pu[deg - j] * pv[j];
}

}  // namespace

int fit_terms(FitModel model) {
  const int lo = min_degree(model), hi = max_degree(model);
  return (hi + 1) * (hi + 2) / 2 - lo * (lo + 1) / 2;
}

HeightFit fit_height(FitModel model, const double* u, const double* v, const double* d, int count,
                     double min_rcond) {
  HeightFit fit;
  const int terms = fit_terms(model);
  if (count < terms) return fit;
  double scale = 0.0;
  for (int j = 0; j < count; ++j) scale = std::max(scale, std::hypot(u[j], v[j]));
  if (!(scale > 0.0) || !std::isfinite(scale)) return fit;
  // The design matrix in a per-thread buffer (no heap per vertex), then
  // A^T A and A^T d as matrix products, which Eigen vectorises.
  thread_local std::vector<double> buffer;
  if (buffer.size() < size_t(count) * size_t(terms + 1)) buffer.resize(size_t(count) * size_t(terms + 1));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> a(buffer.data(), count, terms);
  Eigen::Map<Eigen::VectorXd> rhs(buffer.data() + size_t(count) * size_t(terms), count);
  for (int j = 0; j < count; ++j) {
    monomials(model, u[j] / scale, v[j] / scale, &a(j, 0));
    rhs(j) = d[j];
  }
  Normal ata = Normal::Zero(terms, terms);
  ata.selfadjointView<Eigen::Lower>().rankUpdate(a.transpose());
  const Column atd = a.transpose() * rhs;
  const Eigen::LDLT<Normal, Eigen::Lower> ldlt(ata);
  const auto diag = ldlt.vectorD();
  const double hi = diag.cwiseAbs().maxCoeff(), lo = diag.minCoeff();
  fit.rcond = hi > 0.0 ? lo / hi : 0.0;
  if (ldlt.info() != Eigen::Success || !(fit.rcond >= min_rcond)) return fit;
  const Column c = ldlt.solve(atd);
  if (!c.allFinite()) return fit;
  // Back from the scaled coordinates: a coefficient of u^i v^j carries
  // scale^-(i+j). Linear terms come first (u, v), then u^2, u v, v^2.
  const int q = min_degree(model) == 1 ? 2 : 0;
  if (q) {
    fit.fu = c(0) / scale;
    fit.fv = c(1) / scale;
  }
  const double s2 = scale * scale;
  fit.fuu = 2.0 * c(q) / s2;
  fit.fuv = c(q + 1) / s2;
  fit.fvv = 2.0 * c(q + 2) / s2;
  fit.ok = true;
  return fit;
}

}  // namespace isoform
