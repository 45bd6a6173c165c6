// OSPA (Schuhmacher et al. 2008, Sec. III-A) and GOSPA with alpha = 2 (Rahmathullah et al.
// 2017, Prop. 1) from one assignment on min(d, c)^p; formulas in ospa_gospa.hpp.
#include "skytrack/metrics/ospa_gospa.hpp"

#include <algorithm>
#include <cmath>

namespace skytrack::metrics {

bool is_valid(const OspaGospaConfig& config) {
  return std::isfinite(config.cutoff) && config.cutoff > 0.0 && std::isfinite(config.order) &&
         config.order >= 1.0;
}

double common_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::Index dims = std::min(a.size(), b.size());
  return (a.head(dims) - b.head(dims)).norm();
}

const OspaGospaResult& OspaGospa::compute(std::span<const Eigen::VectorXd> truths,
                                          std::span<const Eigen::VectorXd> estimates) noexcept {
  const double c = config_.cutoff;
  const double p = config_.order;
  const double c_p = std::pow(c, p);
  const auto m = static_cast<Eigen::Index>(truths.size());
  const auto n = static_cast<Eigen::Index>(estimates.size());

  result_.pairs.clear();
  result_.localisation = 0.0;

  // Grow-only workspaces; the solver sees the top-left m x n block.
  if (cost_.rows() < m || cost_.cols() < n) {
    cost_.resize(std::max(m, cost_.rows()), std::max(n, cost_.cols()));
    distance_.resize(cost_.rows(), cost_.cols());
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = 0; i < m; ++i) {
      const double d = common_distance(truths[i], estimates[j]);
      distance_(i, j) = d;
      cost_(i, j) = d < c ? std::pow(d, p) : c_p;
    }
  }
  const AssignmentResult& assignment = solver_.solve(cost_.topLeftCorner(m, n));

  for (Eigen::Index i = 0; i < m; ++i) {
    const int j = assignment.row_to_col[i];
    if (j < 0 || !(distance_(i, j) < c)) continue;  // a pair at d >= c is a miss + a false
    result_.pairs.push_back({static_cast<int>(i), j, distance_(i, j)});
    result_.localisation += cost_(i, j);
  }
  const auto matched = static_cast<Eigen::Index>(result_.pairs.size());
  result_.missed = static_cast<int>(m - matched);
  result_.false_tracks = static_cast<int>(n - matched);

  // GOSPA^p = localisation + c^p/2 (missed + false)
  const double gospa_p = result_.localisation + 0.5 * c_p * (result_.missed + result_.false_tracks);
  result_.gospa = std::pow(gospa_p, 1.0 / p);

  // OSPA^p = (sum min(d,c)^p + c^p |n - m|) / max(m, n) = (loc + c^p (max - matched)) / max
  const Eigen::Index larger = std::max(m, n);
  result_.ospa =
      larger == 0 ? 0.0
                  : std::pow((result_.localisation + c_p * static_cast<double>(larger - matched)) /
                                 static_cast<double>(larger),
                             1.0 / p);
  return result_;
}

OspaGospaResult ospa_gospa(std::span<const Eigen::VectorXd> truths,
                           std::span<const Eigen::VectorXd> estimates,
                           const OspaGospaConfig& config) {
  OspaGospa calculator(config);
  return calculator.compute(truths, estimates);
}

double ospa(std::span<const Eigen::VectorXd> truths, std::span<const Eigen::VectorXd> estimates,
            const OspaGospaConfig& config) {
  return ospa_gospa(truths, estimates, config).ospa;
}

double gospa(std::span<const Eigen::VectorXd> truths, std::span<const Eigen::VectorXd> estimates,
             const OspaGospaConfig& config) {
  return ospa_gospa(truths, estimates, config).gospa;
}

}  // namespace skytrack::metrics
