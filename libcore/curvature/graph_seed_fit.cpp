// The seed's osculating-quadric fit on the platelet (Section 4.3).
#include "graph_seed_fit.h"

#include <Eigen/Eigenvalues>

#include "graph_frame.h"
#include "graph_platelet.h"

namespace isoform {
namespace {

// Reciprocal condition number below which U^T U counts as singular: the
// rows scale as h^2 on both sides, so the ratio is free of the voxel size.
constexpr double kMinReciprocalCondition = 1e-10;

bool axis_derivative(const GraphSamples& s, int axis, double& d) {
  auto def = [&](int t) {
    int o[3] = {0, 0, 0};
    o[axis] = t;
    return s.is_defined(o[0], o[1], o[2]);
  };
  auto val = [&](int t) {
    int o[3] = {0, 0, 0};
    o[axis] = t;
    return s.value(o[0], o[1], o[2]);
  };
  if (def(1) && def(-1)) d = (val(1) - val(-1)) / 2;
  else if (def(1) && def(2)) d = (-3 * val(0) + 4 * val(1) - val(2)) / 2;
  else if (def(-1) && def(-2)) d = (3 * val(0) - 4 * val(-1) + val(-2)) / 2;
  else if (def(1)) d = val(1) - val(0);
  else if (def(-1)) d = val(0) - val(-1);
  else return false;
  return true;
}

}  // namespace

bool graph_grid_gradient(const GraphSamples& s, const GraphAxes& axes, std::array<double, 3>& g) {
  std::array<double, 3> gi;
  for (int a = 0; a < 3; ++a)
    if (!axis_derivative(s, a, gi[size_t(a)])) return false;
  g = axes.world_gradient(gi);
  return true;
}

GraphSeedFit graph_seed_fit(const GraphSamples& s, const GraphAxes& axes, const std::array<double, 3>& g) {
  GraphSeedFit out;
  const GraphFrame frame = graph_frame(g);
  const double f0 = s.value(0, 0, 0);
  using Mat6 = Eigen::Matrix<double, 6, 6>;
  using Vec6 = Eigen::Matrix<double, 6, 1>;
  Mat6 utu = Mat6::Zero();
  Vec6 utd = Vec6::Zero();
  for (const auto& o : graph_platelet_offsets()) {
    if (!s.is_defined(o[0], o[1], o[2])) continue;
    const auto x = axes.world_offset(o[0], o[1], o[2]);
    const GraphLocal p = graph_local(frame, {x[0], x[1], x[2], s.value(o[0], o[1], o[2]) - f0});
    Vec6 row;
    row << 0.5 * p.u * p.u, p.u * p.v, p.u * p.w, 0.5 * p.v * p.v, p.v * p.w, 0.5 * p.w * p.w;
    utu += row * row.transpose();
    utd += row * p.d;
    ++out.points;
  }
  if (out.points < 6) return out;
  // The eigen-decomposition both checks the conditioning and solves.
  const Eigen::SelfAdjointEigenSolver<Mat6> eig(utu);
  const Vec6 lambda = eig.eigenvalues();
  if (!(lambda[0] > kMinReciprocalCondition * lambda[5])) return out;
  const Vec6 c = eig.eigenvectors() * ((eig.eigenvectors().transpose() * utd).cwiseQuotient(lambda));
  const Sym3 m = {{{c[0], c[1], c[2]}, {c[1], c[3], c[4]}, {c[2], c[4], c[5]}}};
  out.curvature = graph_principal_symmetric(m);
  out.ok = true;
  return out;
}

}  // namespace isoform
