#include "skytrack/tracking/track_life.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace skytrack {

TrackLife initiated_life(int plots, int scans) noexcept {
  TrackLife life;
  life.scans = std::max(1, scans);
  life.hits = plots;
  // The first and the last initiating plots bound the window; the others sit just before
  // the last one (which scans they came from does not matter for M-of-N).
  const int span = std::min(life.scans, 32);
  life.history = 1u | (1u << (span - 1));
  for (int i = 1; i < plots - 1 && i < span - 1; ++i) life.history |= 1u << i;
  return life;
}

double scan_support(double best_ratio, double detection_probability,
                    double gate_probability) noexcept {
  const double plot = std::isfinite(best_ratio) ? detection_probability * best_ratio : 0.0;
  return std::log(std::max({1.0 - detection_probability * gate_probability, plot, 1e-300}));
}

void update_existence(TrackLife& life, double likelihood_ratio, double detection_probability,
                      double gate_probability, const config::TrackLifeSpec& spec) noexcept {
  const double predicted = spec.survival_probability * life.existence;
  const double ratio = std::isfinite(likelihood_ratio) ? std::max(likelihood_ratio, 0.0) : 0.0;
  const double delta = detection_probability * (gate_probability - ratio);
  const double updated = (1.0 - delta) * predicted / (1.0 - delta * predicted);
  // Kept off 0 and 1 so that later scans can still move it.
  life.existence = std::isfinite(updated) ? std::clamp(updated, 1e-9, 1.0 - 1e-9) : predicted;
}

namespace {
double predicted_detectability(const TrackLife& life,
                               const config::DetectabilitySpec& spec) noexcept {
  return (1.0 - spec.hide) * life.detectable + spec.reveal * (1.0 - life.detectable);
}
}  // namespace

double support_detection_probability(const TrackLife& life, double detection_probability,
                                     const config::DetectabilitySpec& spec) noexcept {
  return detection_probability * predicted_detectability(life, spec);
}

void update_detectability(TrackLife& life, double likelihood_ratio, double detection_probability,
                          double gate_probability, const config::DetectabilitySpec& spec) noexcept {
  const double predicted = predicted_detectability(life, spec);
  const double ratio = std::isfinite(likelihood_ratio) ? std::max(likelihood_ratio, 0.0) : 0.0;
  const double seen = predicted * (1.0 - detection_probability * (gate_probability - ratio));
  const double updated = seen / (seen + 1.0 - predicted);
  life.detectable = std::isfinite(updated) ? std::clamp(updated, 1e-9, 1.0) : predicted;
}

double existence_to_outlive_a_miss(double detection_probability, double gate_probability,
                                   const config::TrackLifeSpec& spec,
                                   const config::DetectabilitySpec& detectability) noexcept {
  if (spec.confirmation != config::ConfirmationMethod::kExistence) return 0.0;
  const TrackLife fresh;
  const double pd = support_detection_probability(fresh, detection_probability, detectability);
  // update_existence with no plot, solved for the predicted existence that lands on the
  // deletion threshold d: (1 - delta) p / (1 - delta p) = d.
  const double delta = pd * gate_probability;
  const double d = spec.delete_existence;
  const double predicted = d / (1.0 - delta + delta * d);
  return std::min(1.0, predicted / spec.survival_probability);
}

LifeChange advance_life(TrackLife& life, bool detected, double position_sigma,
                        const config::TrackLifeSpec& spec) noexcept {
  LifeChange change;
  life.history = (life.history << 1) | (detected ? 1u : 0u);
  ++life.scans;
  if (detected) {
    ++life.hits;
    life.consecutive_misses = 0;
  } else {
    ++life.consecutive_misses;
  }

  const bool by_existence = spec.confirmation == config::ConfirmationMethod::kExistence;
  const bool unlikely = by_existence && life.existence < spec.delete_existence;
  const bool firm = life.status == TrackStatus::kConfirmed || life.status == TrackStatus::kCoasting;
  if (!firm) {
    const int window = std::min(spec.confirm_n, 32);
    const std::uint32_t mask = window == 32 ? 0xFFFFFFFFu : (1u << window) - 1u;
    const bool confirm = by_existence ? life.existence >= spec.confirm_existence
                                      : std::popcount(life.history & mask) >= spec.confirm_m;
    if (confirm) {
      life.status = TrackStatus::kConfirmed;
      change.confirmed = true;
    } else if (unlikely || life.consecutive_misses >= spec.delete_tentative_misses ||
               position_sigma > spec.delete_position_sigma) {
      life.status = TrackStatus::kDeleted;
      change.deleted = true;
    }
    return change;
  }
  if (unlikely || life.consecutive_misses >= spec.delete_confirmed_misses ||
      position_sigma > spec.delete_position_sigma) {
    life.status = TrackStatus::kDeleted;
    change.deleted = true;
  } else if (!detected) {
    change.started_coasting = life.status != TrackStatus::kCoasting;
    life.status = TrackStatus::kCoasting;
  } else {
    life.status = TrackStatus::kConfirmed;
  }
  return change;
}

}  // namespace skytrack
