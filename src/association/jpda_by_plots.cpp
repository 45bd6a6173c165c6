// Exact JPDA over the shared plots: the transposed problem (jpda_by_plots.hpp).
#include "skytrack/association/jpda_by_plots.hpp"

#include <algorithm>
#include <cstddef>

#include "jpda_input.hpp"

namespace skytrack {
namespace {

std::size_t at(Eigen::Index i) {
  return static_cast<std::size_t>(i);
}

}  // namespace

bool JpdaByPlots::plan(const Eigen::Ref<const Eigen::MatrixXd>& weights) noexcept {
  const Eigen::Index tracks = weights.rows(), columns = weights.cols();
  detail::find_shared_plots(weights, shared_, is_shared_);
  if (shared_.empty()) return false;
  stay_.assign(at(tracks), 0.0);
  stay_events_.assign(at(tracks), 0);
  for (Eigen::Index t = 0; t < tracks; ++t) {
    for (Eigen::Index c = 0; c < columns; ++c) {
      if (weights(t, c) > 0.0 && (c == 0 || is_shared_[at(c)] == 0)) {
        stay_[at(t)] += weights(t, c);
        ++stay_events_[at(t)];
      }
    }
    if (!(stay_[at(t)] > 0.0)) return false;
  }
  const auto rows = static_cast<Eigen::Index>(shared_.size());
  transposed_.resize(at(rows * (1 + tracks)));
  Eigen::Map<Eigen::MatrixXd> w(transposed_.data(), rows, 1 + tracks);
  for (Eigen::Index p = 0; p < rows; ++p) {
    w(p, 0) = 1.0;  // the plot is clutter
    for (Eigen::Index t = 0; t < tracks; ++t) {
      w(p, 1 + t) = weights(t, shared_[at(p)]) / stay_[at(t)];
    }
    w.row(p) /= w.row(p).maxCoeff();  // each row takes one entry: no marginal changes
  }
  exact_.plan(w, stay_events_);
  return true;
}

JpdaExactOutcome JpdaByPlots::run(const Eigen::Ref<const Eigen::MatrixXd>& weights,
                                  std::int64_t max_states,
                                  Eigen::Ref<Eigen::MatrixXd> beta) noexcept {
  const Eigen::Index tracks = weights.rows(), columns = weights.cols();
  const auto rows = static_cast<Eigen::Index>(shared_.size());
  const Eigen::Map<const Eigen::MatrixXd> w(transposed_.data(), rows, 1 + tracks);
  transposed_beta_.resize(transposed_.size());
  Eigen::Map<Eigen::MatrixXd> by_plot(transposed_beta_.data(), rows, 1 + tracks);
  const JpdaExactOutcome outcome = exact_.run(w, max_states, by_plot);
  if (!outcome.completed || !(outcome.total_weight > 0.0)) return outcome;
  beta.setZero();
  for (Eigen::Index t = 0; t < tracks; ++t) {
    double taken = 0.0;
    for (Eigen::Index p = 0; p < rows; ++p) {
      beta(t, shared_[at(p)]) = by_plot(p, 1 + t);
      taken += by_plot(p, 1 + t);
    }
    const double unused = std::max(0.0, 1.0 - taken) / stay_[at(t)];
    for (Eigen::Index c = 0; c < columns; ++c) {
      if (c == 0 || (is_shared_[at(c)] == 0 && weights(t, c) > 0.0)) {
        beta(t, c) = unused * weights(t, c);
      }
    }
  }
  return outcome;
}

}  // namespace skytrack
