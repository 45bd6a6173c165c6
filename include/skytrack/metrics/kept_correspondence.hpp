#pragma once
// The truth-to-track correspondence of the CLEAR MOT metrics (Bernardin & Stiefelhagen 2008,
// "Evaluating multiple object tracking performance", EURASIP JIVP): a truth keeps the track
// it was last matched to while that track is reported firm and within the cut-off; the
// truths without one are matched to the tracks left by a minimum-distance assignment within
// the cut-off. A track number then changes on an object only when another track takes it
// over, not when two objects overlap and one frame's optimal (GOSPA) assignment flips
// between their tracks, which the per-frame assignment counts as changes on both objects.
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/association/assignment.hpp"

namespace skytrack::metrics {

class KeptCorrespondence {
 public:
  explicit KeptCorrespondence(double cutoff) : cutoff_(cutoff) {}

  /// One frame. `distances`: truths x tracks [m]; a pair at or beyond the cut-off (or not
  /// finite) is never matched. `matched` gets, per truth, its track id or nullopt.
  void match(std::span<const std::int64_t> truth_ids, std::span<const std::int64_t> track_ids,
             const Eigen::MatrixXd& distances, std::vector<std::optional<std::int64_t>>& matched);

 private:
  bool allowed(double distance) const { return distance < cutoff_; }

  double cutoff_;
  std::map<std::int64_t, std::int64_t> last_;  // truth id -> the track it was last matched to
  AssignmentSolver solver_;
  std::vector<int> free_truths_, free_tracks_;
  std::vector<char> track_taken_;
  Eigen::MatrixXd cost_;
};

}  // namespace skytrack::metrics
