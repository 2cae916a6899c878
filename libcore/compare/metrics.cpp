#include "metrics.h"

#include <algorithm>
#include <cmath>

namespace isoform::compare {

void StatsSum::add(double x) {
  const double a = std::abs(x);
  ++n_;
  max_ = std::max(max_, a);
  sum_ += a;
  sum2_ += a * a;
}

void StatsSum::merge(const StatsSum& o) {
  n_ += o.n_;
  max_ = std::max(max_, o.max_);
  sum_ += o.sum_;
  sum2_ += o.sum2_;
}

Stats StatsSum::stats() const {
  Stats s;
  s.count = n_;
  if (n_ == 0) return s;
  s.max = max_;
  s.mean = sum_ / double(n_);
  s.rms = std::sqrt(sum2_ / double(n_));
  return s;
}

Spread spread_of(std::vector<double> v) {
  Spread s;
  s.count = (long long)v.size();
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  auto rank = [&](double p) { return v[std::min(v.size() - 1, size_t(std::ceil(p * double(v.size()))) - (p > 0 ? 1 : 0))]; };
  s.p05 = rank(0.05);
  s.p50 = rank(0.50);
  s.p95 = rank(0.95);
  double sum = 0.0;
  for (double x : v) sum += x;
  s.mean = sum / double(v.size());
  double var = 0.0;
  for (double x : v) var += (x - s.mean) * (x - s.mean);
  s.stddev = std::sqrt(var / double(v.size()));
  return s;
}

}  // namespace isoform::compare
