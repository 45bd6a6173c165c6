// The split of a shared partition by fitted clusters (see extended_tracker.hpp): the
// partition's plots are fitted as k Gaussian clusters from a start that does not use the
// tracks (principal-axis split, then farthest-first), and the clusters are given to the
// tracks as wholes by the least total cost over every map of clusters to tracks.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "skytrack/extended/extended_tracker.hpp"

namespace skytrack::extended {
namespace {

constexpr double kScatter = 0.25;  // covariance of a point uniform over E(0, X) is X / 4
constexpr int kFitIterations = 10;
constexpr int kMaxClusters = 4;  // maps of clusters to tracks tried exhaustively: 4^4

double cost_under(const Eigen::Matrix2d& cov, const Eigen::Vector2d& nu) {
  const Eigen::LLT<Eigen::Matrix2d> llt(cov);
  if (llt.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
  return nu.dot(llt.solve(nu)) + 2.0 * std::log(llt.matrixL()(0, 0) * llt.matrixL()(1, 1));
}

}  // namespace

bool ExtendedTracker::split_by_clusters(const std::vector<int>& group) {
  const int k = static_cast<int>(gated_.size());
  const int n = static_cast<int>(group.size());
  if (k < 2 || k > kMaxClusters || n < 2 * k) return false;
  // Start: the plots' principal axis, cut at the mean for two clusters; more clusters
  // farthest-first from the plot farthest from the mean.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  Eigen::Matrix2d noise = Eigen::Matrix2d::Zero();
  for (int i : group) mean += positions_[i], noise += noises_[i];
  mean /= n;
  noise /= n;
  std::vector<int>& label = split_owner_;
  label.assign(n, 0);
  if (k == 2) {
    Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
    for (int i : group)
      scatter.noalias() += (positions_[i] - mean) * (positions_[i] - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(scatter);
    const Eigen::Vector2d axis = eig.eigenvectors().col(1);
    for (int p = 0; p < n; ++p) label[p] = axis.dot(positions_[group[p]] - mean) > 0.0 ? 1 : 0;
  } else {
    std::array<int, kMaxClusters> seed{};
    auto farthest = [&](int chosen) {
      int best = 0;
      double best_d = -1.0;
      for (int p = 0; p < n; ++p) {
        double d = chosen == 0 ? (positions_[group[p]] - mean).squaredNorm()
                               : std::numeric_limits<double>::infinity();
        for (int c = 0; c < chosen; ++c) {
          d = std::min(d, (positions_[group[p]] - positions_[group[seed[c]]]).squaredNorm());
        }
        if (d > best_d) best_d = d, best = p;
      }
      return best;
    };
    for (int c = 0; c < k; ++c) seed[c] = farthest(c);
    for (int p = 0; p < n; ++p) {
      double best_d = std::numeric_limits<double>::infinity();
      for (int c = 0; c < k; ++c) {
        const double d = (positions_[group[p]] - positions_[group[seed[c]]]).squaredNorm();
        if (d < best_d) best_d = d, label[p] = c;
      }
    }
  }
  // Fit: classification EM of k Gaussians, each covariance floored at the noise and a
  // new object's spread (a cluster of two or three plots is not a point).
  const double floor = kScatter * spec_.initial_extent_axis * spec_.initial_extent_axis;
  std::array<Eigen::Vector2d, kMaxClusters> centre;
  std::array<Eigen::Matrix2d, kMaxClusters> cov;
  std::array<int, kMaxClusters> count{};
  auto estimate = [&] {
    for (int c = 0; c < k; ++c) centre[c].setZero(), cov[c].setZero(), count[c] = 0;
    for (int p = 0; p < n; ++p) centre[label[p]] += positions_[group[p]], ++count[label[p]];
    for (int c = 0; c < k; ++c) {
      if (count[c] > 0) centre[c] /= count[c];
    }
    for (int p = 0; p < n; ++p) {
      const Eigen::Vector2d d = positions_[group[p]] - centre[label[p]];
      cov[label[p]].noalias() += d * d.transpose();
    }
    for (int c = 0; c < k; ++c) {
      if (count[c] > 0) cov[c] /= count[c];
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov[c]);
      const Eigen::Vector2d axes = eig.eigenvalues().cwiseMax(floor);
      cov[c] = eig.eigenvectors() * axes.asDiagonal() * eig.eigenvectors().transpose() + noise;
    }
  };
  for (int iteration = 0; iteration < kFitIterations; ++iteration) {
    estimate();
    if (std::any_of(count.begin(), count.begin() + k, [](int c) { return c == 0; })) return false;
    bool moved = false;
    for (int p = 0; p < n; ++p) {
      int best = label[p];
      double best_cost = std::numeric_limits<double>::infinity();
      for (int c = 0; c < k; ++c) {
        const double cost = cost_under(cov[c], positions_[group[p]] - centre[c]);
        if (cost < best_cost) best_cost = cost, best = c;
      }
      moved |= best != label[p];
      label[p] = best;
    }
    if (!moved) break;
  }
  estimate();
  if (std::any_of(count.begin(), count.begin() + k, [](int c) { return c == 0; })) return false;
  // Only plots that are k clusters (BIC against one cluster: 6 parameters a further
  // cluster) are split this way; one object's plots, or objects overlapping into one
  // cloud, are left to the split from the predictions.
  double cost_k = 0.0;
  for (int p = 0; p < n; ++p) {
    cost_k += cost_under(cov[label[p]], positions_[group[p]] - centre[label[p]]) -
              2.0 * std::log(static_cast<double>(count[label[p]]) / n);
  }
  Eigen::Matrix2d whole = Eigen::Matrix2d::Zero();
  for (int i : group)
    whole.noalias() += (positions_[i] - mean) * (positions_[i] - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> whole_eig(whole / n);
  const Eigen::Matrix2d whole_cov = whole_eig.eigenvectors() *
                                        whole_eig.eigenvalues().cwiseMax(floor).asDiagonal() *
                                        whole_eig.eigenvectors().transpose() +
                                    noise;
  double cost_1 = 0.0;
  for (int i : group) cost_1 += cost_under(whole_cov, positions_[i] - mean);
  if (cost_k + 6.0 * (k - 1) * std::log(static_cast<double>(n)) >= cost_1) return false;
  // Hypotheses: every map of the clusters to the tracks (a track may take several or none:
  // an object unseen this scan, or one object's plots cut in two). Each track's cost is -2 ln
  // of the likelihood of its plots given it: their mean about the predicted centre under
  // HPH' + Sigma / m and their scatter under Sigma = X/4 + R (m plots; centre and velocity
  // through the prediction, shape and orientation through Sigma), and -2 ln P_D; a track
  // without plots -2 ln (1 - P_D).
  const PosMat H = position_matrix();
  const double pd = spec_.existence.detection_probability;
  const double seen = -2.0 * std::log(std::max(pd, 1e-9));
  const double unseen = -2.0 * std::log(std::max(1.0 - pd, 1e-9));
  auto track_cost = [&](int g, unsigned clusters) {
    if (clusters == 0) return unseen;
    const int t = gated_[g].track;
    Eigen::Vector2d m_centre = Eigen::Vector2d::Zero();
    int m = 0;
    for (int p = 0; p < n; ++p) {
      if (clusters >> label[p] & 1u) m_centre += positions_[group[p]], ++m;
    }
    m_centre /= m;
    Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
    for (int p = 0; p < n; ++p) {
      if (!(clusters >> label[p] & 1u)) continue;
      const Eigen::Vector2d d = positions_[group[p]] - m_centre;
      scatter.noalias() += d * d.transpose();
    }
    const Eigen::Matrix2d sigma = kScatter * association_extents_[t] + noise;
    const Eigen::LLT<Eigen::Matrix2d> llt(sigma);
    if (llt.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
    const double log_det = 2.0 * std::log(llt.matrixL()(0, 0) * llt.matrixL()(1, 1));
    const Eigen::Matrix2d prior = H * tracks_[t].object.P * H.transpose();
    return seen + cost_under(prior + sigma / m, m_centre - tracks_[t].position()) +
           llt.solve(scatter).trace() + (m - 1.0) * log_det;
  };
  int hypotheses = 1;
  for (int c = 0; c < k; ++c) hypotheses *= k;
  std::array<int, kMaxClusters> owner{}, best_owner{};  // owner[c]: cluster c's track
  double best_total = std::numeric_limits<double>::infinity();
  for (int h = 0; h < hypotheses; ++h) {
    for (int c = 0, code = h; c < k; ++c, code /= k) owner[c] = code % k;
    unsigned used = 0;
    for (int c = 0; c < k; ++c) used |= 1u << owner[c];
    if (used != (1u << k) - 1u) continue;  // one cluster per track
    double total = 0.0;
    for (int g = 0; g < k; ++g) {
      unsigned clusters = 0;
      for (int c = 0; c < k; ++c) clusters |= owner[c] == g ? 1u << c : 0u;
      total += track_cost(g, clusters);
    }
    if (total < best_total) best_total = total, best_owner = owner;
  }
  if (!std::isfinite(best_total)) return false;
  for (int g = 0; g < k; ++g) {
    const int t = gated_[g].track;
    for (int p = 0; p < n; ++p) {
      if (best_owner[label[p]] != g) continue;
      const int i = group[p];
      if (gate_distance(t, positions_[i], noises_[i], kScatter, nullptr) <= spec_.plot_gate) {
        track_plots_[t].push_back(i);
      }
    }
  }
  return true;
}

}  // namespace skytrack::extended
