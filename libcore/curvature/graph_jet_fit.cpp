// Polynomial (jet) fit of f over a box of grid samples; see graph_jet_fit.h.
#include "graph_jet_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <memory>
#include <mutex>
#include <vector>

namespace isoform {
namespace {

// Measured on Table 4.2 (docs/curvature-volume.md): degree 4 on 5^3 left
// the cosine's RMS K at 1.2e-3 over all points, dominated by one-sided boxes
// at the domain's faces; degree 6 on 7^3 brings it to 1.0e-4 and reproduces
// every polynomial of degree 6.
constexpr int kWidth = 7;   // samples per axis of a full box
constexpr int kDegree = 6;  // total degree of the full-box fit
constexpr int kDerivatives = 9; // f_x, f_y, f_z, f_xx, f_xy, f_xz, f_yy, f_yz, f_zz

using Exponent = std::array<int, 3>;

struct Box {
  int start[3];  // first offset per axis, in [-kGraphReach, 0]
  int width[3];  // 3, 4 or 5
};

// The derivative monomials in the order of kDerivatives, and the factor
// from coefficient to derivative at the origin (2 for pure squares).
const Exponent kDerivativeMonomial[kDerivatives] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0}, {1, 1, 0},
                                                    {1, 0, 1}, {0, 2, 0}, {0, 1, 1}, {0, 0, 2}};
const double kDerivativeFactor[kDerivatives] = {1, 1, 1, 2, 1, 1, 2, 1, 2};

std::vector<Exponent> monomials(int degree, const int cap[3]) {
  std::vector<Exponent> out;
  for (int c = 0; c <= std::min(degree, cap[2]); ++c)
    for (int b = 0; b <= std::min(degree - c, cap[1]); ++b)
      for (int a = 0; a <= std::min(degree - b - c, cap[0]); ++a) out.push_back({a, b, c});
  return out;
}

double power(int base, int e) {
  double r = 1;
  for (int i = 0; i < e; ++i) r *= base;
  return r;
}

// The run of defined samples along `axis` through the point, as a box side.
bool box_side(const GraphSamples& s, int axis, int& start, int& width) {
  auto def = [&](int t) {
    int o[3] = {0, 0, 0};
    o[axis] = t;
    return s.is_defined(o[0], o[1], o[2]);
  };
  int lo = 0, hi = 0;
  while (lo > -kGraphReach && def(lo - 1)) --lo;
  while (hi < kGraphReach && def(hi + 1)) ++hi;
  width = std::min(kWidth, hi - lo + 1);
  if (width < 3) return false;
  start = width == kWidth ? std::clamp(-kWidth / 2, lo, hi - (kWidth - 1)) : lo;
  return true;
}

// Rows of the least-squares operator that give the 9 derivatives at the
// origin from the box's samples (x fastest), for one box shape.
struct Operator {
  int samples = 0;
  std::vector<double> rows;  // kDerivatives x samples
};

Operator build_operator(const Box& box) {
  const int cap[3] = {std::min(kDegree, box.width[0] - 1), std::min(kDegree, box.width[1] - 1),
                      std::min(kDegree, box.width[2] - 1)};
  const std::vector<Exponent> mono = monomials(kDegree, cap);
  Operator op;
  op.samples = box.width[0] * box.width[1] * box.width[2];
  Eigen::MatrixXd a(op.samples, Eigen::Index(mono.size()));
  int r = 0;
  for (int k = 0; k < box.width[2]; ++k)
    for (int j = 0; j < box.width[1]; ++j)
      for (int i = 0; i < box.width[0]; ++i, ++r)
        for (size_t m = 0; m < mono.size(); ++m)
          a(r, Eigen::Index(m)) = power(box.start[0] + i, mono[m][0]) * power(box.start[1] + j, mono[m][1]) *
                                  power(box.start[2] + k, mono[m][2]);
  const Eigen::MatrixXd pinv = a.completeOrthogonalDecomposition().pseudoInverse();
  op.rows.resize(size_t(kDerivatives) * size_t(op.samples));
  for (int d = 0; d < kDerivatives; ++d) {
    const size_t m = size_t(std::find(mono.begin(), mono.end(), kDerivativeMonomial[d]) - mono.begin());
    for (int c = 0; c < op.samples; ++c)
      op.rows[size_t(d) * size_t(op.samples) + size_t(c)] = kDerivativeFactor[d] * pinv(Eigen::Index(m), c);
  }
  return op;
}

// One operator per box shape, built on first use. Per axis a shape is a
// width (3, 4, 5) and a start in [-kGraphReach, 0].
const Operator& operator_for(const Box& box) {
  constexpr int kStarts = kGraphReach + 1;
  constexpr int kShapes = (kWidth - 2) * kStarts;
  struct Slot {
    std::once_flag once;
    Operator op;
  };
  static std::vector<Slot> slots(size_t(kShapes) * kShapes * kShapes);
  size_t key = 0;
  for (int a = 2; a >= 0; --a) key = key * kShapes + size_t((box.width[a] - 3) * kStarts + box.start[a] + kGraphReach);
  Slot& slot = slots[key];
  std::call_once(slot.once, [&] { slot.op = build_operator(box); });
  return slot.op;
}

// Index-space derivatives (gradient, then the upper triangle of the Hessian)
// from a full box.
void apply_operator(const GraphSamples& s, const Box& box, double f0, double d[kDerivatives]) {
  const Operator& op = operator_for(box);
  std::fill(d, d + kDerivatives, 0.0);
  int c = 0;
  for (int k = 0; k < box.width[2]; ++k)
    for (int j = 0; j < box.width[1]; ++j)
      for (int i = 0; i < box.width[0]; ++i, ++c) {
        const double v = s.value(box.start[0] + i, box.start[1] + j, box.start[2] + k) - f0;
        for (int e = 0; e < kDerivatives; ++e) d[e] += op.rows[size_t(e) * size_t(op.samples) + size_t(c)] * v;
      }
}

// The 10 monomials of degree 2 at an integer offset, in the order of
// monomials(2, {2, 2, 2}): 1, x, x^2, y, xy, y^2, z, xz, yz, z^2.
constexpr int kQuadratic = 10;

// Index in kMoments of x^a y^b z^c, a + b + c <= 4 (35 moments).
constexpr int kMomentDegree = 4;
constexpr int kMoments = 35;

int moment_index(int a, int b, int c) {
  static const auto table = [] {
    std::array<int, 125> t{};
    int n = 0;
    for (int cc = 0; cc <= kMomentDegree; ++cc)
      for (int bb = 0; bb + cc <= kMomentDegree; ++bb)
        for (int aa = 0; aa + bb + cc <= kMomentDegree; ++aa) t[size_t(aa + 5 * (bb + 5 * cc))] = n++;
    return t;
  }();
  return table[size_t(a + 5 * (b + 5 * c))];
}

// Degree 2 over the defined samples of a box with holes; false when the
// 10x10 normal equations are ill-conditioned.
//
// The normal matrix's entries are sums of monomials x^a y^b z^c (a + b + c
// <= 4) over the defined integer offsets, each below 6^4, over at most 7^3
// samples: integers far below 2^53, so summing the 35 moments in integer
// arithmetic (powers of x per row, then spread over y^b z^c per row) and
// spreading them gives exactly the matrix that summing the 10x10 outer
// products in doubles gives, for a fraction of the work. The right-hand
// side is summed as before, in the same order, so the bits are the same.
bool reduced_fit(const GraphSamples& s, const Box& box, double f0, double d[kDerivatives]) {
  const int cap[3] = {2, 2, 2};
  const std::vector<Exponent> mono = monomials(2, cap);
  using Mat10 = Eigen::Matrix<double, kQuadratic, kQuadratic>;
  using Vec10 = Eigen::Matrix<double, kQuadratic, 1>;
  long long moment[kMoments] = {};
  Vec10 rhs = Vec10::Zero();
  for (int k = 0; k < box.width[2]; ++k)
    for (int j = 0; j < box.width[1]; ++j) {
      const int y = box.start[1] + j, z = box.start[2] + k;
      // Powers of x summed along the row, then spread over y^b z^c once.
      long long sx[kMomentDegree + 1] = {};
      for (int i = 0; i < box.width[0]; ++i) {
        const int x = box.start[0] + i;
        if (!s.is_defined(x, y, z)) continue;
        const long long xx = x * x;
        sx[0] += 1;
        sx[1] += x;
        sx[2] += xx;
        sx[3] += xx * x;
        sx[4] += xx * xx;
        const double row[kQuadratic] = {1,
                                        double(x),
                                        double(xx),
                                        double(y),
                                        double(x * y),
                                        double(y * y),
                                        double(z),
                                        double(x * z),
                                        double(y * z),
                                        double(z * z)};
        const double v = s.value(x, y, z) - f0;
        for (int q = 0; q < kQuadratic; ++q) rhs[q] += row[q] * v;
      }
      if (sx[0] == 0) continue;
      const long long py[5] = {1, y, y * y, y * y * y, y * y * y * y};
      const long long pz[5] = {1, z, z * z, z * z * z, z * z * z * z};
      long long* m = moment;
      for (int c = 0; c <= kMomentDegree; ++c)
        for (int b = 0; b + c <= kMomentDegree; ++b) {
          const long long yz = py[b] * pz[c];
          for (int a = 0; a + b + c <= kMomentDegree; ++a) *m++ += sx[a] * yz;
        }
    }
  Mat10 m;
  for (int p = 0; p < kQuadratic; ++p)
    for (int q = 0; q < kQuadratic; ++q) {
      const Exponent& e = mono[size_t(p)];
      const Exponent& f = mono[size_t(q)];
      m(p, q) = double(moment[moment_index(e[0] + f[0], e[1] + f[1], e[2] + f[2])]);
    }
  const Eigen::SelfAdjointEigenSolver<Mat10> eig(m);
  const Vec10 lambda = eig.eigenvalues();
  // Offsets are integers up to kGraphReach, so entries stay below 6^4 per
  // sample; the threshold is relative.
  if (!(lambda[0] > 1e-9 * lambda[9])) return false;
  const Vec10 c = eig.eigenvectors() * ((eig.eigenvectors().transpose() * rhs).cwiseQuotient(lambda));
  for (int e = 0; e < kDerivatives; ++e) {
    const size_t q = size_t(std::find(mono.begin(), mono.end(), kDerivativeMonomial[e]) - mono.begin());
    d[e] = kDerivativeFactor[e] * c[Eigen::Index(q)];
  }
  return true;
}

bool box_is_full(const GraphSamples& s, const Box& box) {
  for (int k = 0; k < box.width[2]; ++k)
    for (int j = 0; j < box.width[1]; ++j)
      for (int i = 0; i < box.width[0]; ++i)
        if (!s.is_defined(box.start[0] + i, box.start[1] + j, box.start[2] + k)) return false;
  return true;
}

// World gradient and Hessian from index-space ones: g_w = L^-T g,
// H_w = L^-T H L^-1.
GraphPrincipal world_curvature(const GraphAxes& axes, const double d[kDerivatives]) {
  const std::array<double, 3> g = axes.world_gradient({d[0], d[1], d[2]});
  const double h[3][3] = {{d[3], d[4], d[5]}, {d[4], d[6], d[7]}, {d[5], d[7], d[8]}};
  const auto& t = axes.inverse_transpose;
  double th[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) th[r][c] = t[r][0] * h[0][c] + t[r][1] * h[1][c] + t[r][2] * h[2][c];
  Sym3 hw;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      hw[size_t(r)][size_t(c)] = th[r][0] * t[c][0] + th[r][1] * t[c][1] + th[r][2] * t[c][2];
  return graph_principal_from_derivatives(g, hw);
}

}  // namespace

GraphJetFit graph_jet_fit(const GraphSamples& s, const GraphAxes& axes) {
  GraphJetFit out;
  Box box;
  for (int a = 0; a < 3; ++a)
    if (!box_side(s, a, box.start[a], box.width[a])) return out;
  const double f0 = s.value(0, 0, 0);
  double d[kDerivatives];
  if (box_is_full(s, box)) {
    apply_operator(s, box, f0, d);
    bool centred = true;
    for (int a = 0; a < 3; ++a) centred = centred && box.width[a] == kWidth && box.start[a] == -kWidth / 2;
    out.kind = centred ? GraphJetKind::Centred : GraphJetKind::Shifted;
  } else {
    if (!reduced_fit(s, box, f0, d)) return out;
    out.kind = GraphJetKind::Reduced;
  }
  out.curvature = world_curvature(axes, d);
  return out;
}

}  // namespace isoform
