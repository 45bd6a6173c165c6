// Paper 004 eq. 9-12 for one pair of tracks (include/skytrack/fusion/track_distance.hpp).
#include "skytrack/fusion/track_distance.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

namespace skytrack::fusion {
namespace {

// Closed form for the common 2-D case: this runs for every scored pair and window scan.
double normalised_squared_2d(const PositionEstimate& a, const PositionEstimate& b) noexcept {
  const double dx = a.mean.x() - b.mean.x(), dy = a.mean.y() - b.mean.y();
  const double sxx = a.cov(0, 0) + b.cov(0, 0) + 1e-6, syy = a.cov(1, 1) + b.cov(1, 1) + 1e-6;
  const double sxy = a.cov(0, 1) + b.cov(0, 1);
  const double det = sxx * syy - sxy * sxy;
  if (!(det > 0.0)) return (dx * dx + dy * dy) / ((sxx + syy) / 2.0) + 2.0;
  return (syy * dx * dx - 2.0 * sxy * dx * dy + sxx * dy * dy) / det + 2.0;
}

template <int N>
double normalised_squared(const PositionEstimate& a, const PositionEstimate& b) noexcept {
  const Eigen::Matrix<double, N, 1> d = (a.mean - b.mean).template head<N>();
  Eigen::Matrix<double, N, N> s =
      a.cov.template topLeftCorner<N, N>() + b.cov.template topLeftCorner<N, N>();
  // A floor keeps a pair of zero-covariance tracks finite (1 mm).
  s.diagonal().array() += 1e-6;
  const Eigen::LLT<Eigen::Matrix<double, N, N>> llt(s);
  if (llt.info() != Eigen::Success) return d.squaredNorm() / (s.trace() / N) + N;
  return d.dot(llt.solve(d)) + N;
}

}  // namespace

double expected_squared_distance(const PositionEstimate& a, const PositionEstimate& b,
                                 Metric metric) noexcept {
  const int n = std::min(a.dims, b.dims) >= 3 ? 3 : 2;
  if (metric == Metric::kNormalised) {
    return n == 3 ? normalised_squared<3>(a, b) : normalised_squared_2d(a, b);
  }
  const Eigen::Vector3d d = a.mean - b.mean;
  double sq = d.head(n).squaredNorm();
  for (int k = 0; k < n; ++k) sq += a.cov(k, k) + b.cov(k, k);
  return sq;
}

double base_distance(double expected_squared, bool labels_differ, const FusionSpec& spec) noexcept {
  const double p = spec.order;
  if (p == 2.0) {  // the usual order, without pow
    const double alpha2 = labels_differ ? spec.label_penalty * spec.label_penalty : 0.0;
    return std::min(spec.cutoff, std::sqrt(std::max(expected_squared, 0.0) + alpha2));
  }
  double sum = std::pow(std::max(expected_squared, 0.0), p / 2.0);
  if (labels_differ) sum += std::pow(spec.label_penalty, p);
  return std::min(spec.cutoff, std::pow(sum, 1.0 / p));
}

double adaptive_beta(double history, double current, double epsilon) noexcept {
  const double sum = history + current;
  if (!(sum > 0.0)) return epsilon / 2.0;
  return epsilon * std::max(history, current) / sum;
}

double blend(double history, double current, const FusionSpec& spec) noexcept {
  const double beta = spec.blend == Blend::kAdaptive ? adaptive_beta(history, current, spec.epsilon)
                                                     : spec.history_weight;
  return beta * history + (1.0 - beta) * current;
}

double history_distance(std::span<const HistoryPoint> a, std::span<const HistoryPoint> b,
                        std::uint64_t cycle, std::uint64_t window_cycles, bool labels_differ,
                        const FusionSpec& spec, double fallback) noexcept {
  const std::uint64_t first = cycle >= window_cycles ? cycle - window_cycles + 1 : 0;
  double sum = 0.0;
  int count = 0;
  // Both histories are sorted by cycle: a merge walk finds the common scans.
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const std::uint64_t ca = a[i].cycle, cb = b[j].cycle;
    if (ca < cb) {
      ++i;
    } else if (cb < ca) {
      ++j;
    } else {
      if (ca >= first && ca < cycle) {
        const double sq = expected_squared_distance(a[i].position, b[j].position, spec.metric);
        sum += base_distance(sq, labels_differ, spec);
        ++count;
      }
      ++i;
      ++j;
    }
  }
  return count > 0 ? sum / count : fallback;
}

double pair_mospa(const PositionEstimate& a, const PositionEstimate& b,
                  std::span<const HistoryPoint> history_a, std::span<const HistoryPoint> history_b,
                  std::uint64_t cycle, std::uint64_t window_cycles, bool labels_differ,
                  const FusionSpec& spec) noexcept {
  const double current =
      base_distance(expected_squared_distance(a, b, spec.metric), labels_differ, spec);
  const double history =
      history_distance(history_a, history_b, cycle, window_cycles, labels_differ, spec, current);
  return blend(history, current, spec);
}

}  // namespace skytrack::fusion
