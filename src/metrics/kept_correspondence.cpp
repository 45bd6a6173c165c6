// CLEAR MOT's kept truth-to-track correspondence (see kept_correspondence.hpp).
#include "skytrack/metrics/kept_correspondence.hpp"

#include <cmath>
#include <limits>

namespace skytrack::metrics {

void KeptCorrespondence::match(std::span<const std::int64_t> truth_ids,
                               std::span<const std::int64_t> track_ids,
                               const Eigen::MatrixXd& distances,
                               std::vector<std::optional<std::int64_t>>& matched) {
  const int truths = static_cast<int>(truth_ids.size());
  const int tracks = static_cast<int>(track_ids.size());
  matched.assign(truths, std::nullopt);
  track_taken_.assign(tracks, 0);
  free_truths_.clear();
  for (int i = 0; i < truths; ++i) {
    const auto last = last_.find(truth_ids[i]);
    int kept = -1;
    if (last != last_.end()) {
      for (int k = 0; k < tracks; ++k) {
        if (track_ids[k] == last->second && !track_taken_[k] && allowed(distances(i, k))) kept = k;
      }
    }
    if (kept < 0) {
      free_truths_.push_back(i);
      continue;
    }
    matched[i] = track_ids[kept];
    track_taken_[kept] = 1;
  }
  free_tracks_.clear();
  for (int k = 0; k < tracks; ++k) {
    if (!track_taken_[k]) free_tracks_.push_back(k);
  }
  if (!free_truths_.empty() && !free_tracks_.empty()) {
    cost_.resize(static_cast<Eigen::Index>(free_truths_.size()),
                 static_cast<Eigen::Index>(free_tracks_.size()));
    for (std::size_t a = 0; a < free_truths_.size(); ++a) {
      for (std::size_t b = 0; b < free_tracks_.size(); ++b) {
        const double d = distances(free_truths_[a], free_tracks_[b]);
        cost_(a, b) = allowed(d) ? d : std::numeric_limits<double>::infinity();
      }
    }
    const AssignmentResult& result = solver_.solve(cost_);
    for (std::size_t a = 0; a < free_truths_.size(); ++a) {
      const int b = result.row_to_col[a];
      if (b >= 0) matched[free_truths_[a]] = track_ids[free_tracks_[b]];
    }
  }
  for (int i = 0; i < truths; ++i) {
    if (matched[i]) last_[truth_ids[i]] = *matched[i];
  }
}

}  // namespace skytrack::metrics
