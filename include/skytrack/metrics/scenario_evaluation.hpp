#pragma once
// Scores a tracker run against ground truth one truth frame at a time, so a long run is
// never held whole: per scan OSPA / GOSPA (ospa_gospa.hpp) with the GOSPA split, and over
// the run means, RMSE over matched pairs, track continuity (track_continuity.hpp; over the
// GOSPA pairs and over CLEAR MOT's kept correspondence, kept_correspondence.hpp) and the
// Gaussian Wasserstein distance of extents (gaussian_wasserstein.hpp).
//
// Only confirmed and coasting tracks are scored (is_reported_as_firm). Positions and
// velocities are compared on the common dimensions (a 2-D truth against a 3-D track uses
// x, y). A truth and a track are "matched" when GOSPA pairs them (d < cutoff).
//
// Default cut-off 100 m: about three times the position error of a filtered track of a
// radar with 2 mrad azimuth noise at 35 km, and well below typical aircraft separations.
// Long-range or coarse sensors should raise it (the CLI's --cutoff).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "skytrack/core/track_report.hpp"
#include "skytrack/core/truth.hpp"
#include "skytrack/metrics/kept_correspondence.hpp"
#include "skytrack/metrics/ospa_gospa.hpp"
#include "skytrack/metrics/track_continuity.hpp"

namespace skytrack::metrics {

struct ScenarioEvaluationConfig {
  double cutoff = 100.0;  // c [m]
  double order = 2.0;     // p
};

/// One truth time.
struct ScanRecord {
  double time = 0.0;                // [s]
  double ospa = 0.0;                // [m]
  double gospa = 0.0;               // [m]
  double gospa_localisation = 0.0;  // sum of d^p over matched pairs [m^p]
  int gospa_missed = 0;             // truths not matched
  int gospa_false = 0;              // firm tracks not matched
  int truths = 0;
  int tracks = 0;  // firm tracks
};

struct EvaluationSummary {
  std::size_t scans = 0;
  double gospa_mean = 0.0;               // [m]
  double ospa_mean = 0.0;                // [m]
  double gospa_localisation_mean = 0.0;  // [m^p] per scan
  double gospa_missed_mean = 0.0;        // truths per scan
  double gospa_false_mean = 0.0;         // tracks per scan
  double rmse_position = 0.0;            // [m] over all matched pairs; NaN if none
  double rmse_velocity = 0.0;            // [m/s] likewise
  std::size_t matched_pairs = 0;
  int id_changes = 0;
  int fragmentations = 0;
  std::vector<TruthContinuity> continuity;  // ordered by truth id
  // The same over CLEAR MOT's kept correspondence (kept_correspondence.hpp): a number
  // change only where another track takes an object over.
  int kept_id_changes = 0;
  int kept_fragmentations = 0;
  double gwd_mean = 0.0;  // [m] mean GW distance over matched pairs with extents; NaN if none
  std::size_t gwd_pairs = 0;
};

class ScenarioEvaluation {
 public:
  explicit ScenarioEvaluation(ScenarioEvaluationConfig config = {});

  /// Scores one truth frame against the tracks reported at its time (null: no tracks).
  const ScanRecord& add(const TruthFrame& truth, const TrackFrame* tracks_or_null);
  const ScanRecord& add(const TruthFrame& truth, std::span<const TrackReport> tracks);

  /// The GOSPA assignment of the last add(): truth indices into truth.objects, estimate
  /// indices into last_firm_tracks().
  const OspaGospaResult& last_result() const { return calculator_.result(); }
  /// Indices (into the tracks passed to the last add()) of the scored firm tracks.
  std::span<const int> last_firm_tracks() const { return firm_; }

  EvaluationSummary summary() const;
  const ScenarioEvaluationConfig& config() const { return config_; }

 private:
  ScenarioEvaluationConfig config_;
  OspaGospa calculator_;
  TrackContinuity continuity_;
  KeptCorrespondence kept_;
  TrackContinuity kept_continuity_;
  ScanRecord record_;
  std::vector<Eigen::VectorXd> truth_positions_, track_positions_;  // reused workspaces
  std::vector<int> firm_;
  std::vector<std::optional<std::int64_t>> matched_track_;  // per truth object
  std::vector<std::optional<std::int64_t>> kept_track_;     // per truth object
  std::vector<std::int64_t> truth_ids_, firm_ids_;
  Eigen::MatrixXd distances_;  // truths x firm tracks [m]

  // Running sums over all scans.
  std::size_t scans_ = 0;
  double sum_gospa_ = 0.0, sum_ospa_ = 0.0, sum_localisation_ = 0.0;
  double sum_missed_ = 0.0, sum_false_ = 0.0;
  double sum_sq_position_ = 0.0, sum_sq_velocity_ = 0.0;
  std::size_t matched_ = 0;
  double sum_gwd_ = 0.0;
  std::size_t gwd_pairs_ = 0;
};

}  // namespace skytrack::metrics
