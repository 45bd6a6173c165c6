#pragma once
// The per-batch composition shared by the daemon and the tools: validation (bad plots and
// out-of-order batches are counted and skipped, never fatal), then, per sensor, the looks of
// a rotating antenna regrouped from whatever batches the feed delivers (antenna_sweep.hpp,
// look_assembler.hpp), then the tracker the profile's mode selects. One Pipeline::process
// call per plot batch, in arrival order; each gives a frame at the batch's time.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "skytrack/config/profile.hpp"
#include "skytrack/core/expected.hpp"
#include "skytrack/core/plot.hpp"
#include "skytrack/core/track_report.hpp"
#include "skytrack/pipeline/batch_clock.hpp"
#include "skytrack/pipeline/estimator_stages.hpp"
#include "skytrack/pipeline/sensor_feed.hpp"
#include "skytrack/pipeline/sensor_timeline.hpp"

namespace skytrack {

/// Totals since the pipeline started, by reason.
struct PipelineCounters {
  std::uint64_t scans_processed = 0;
  std::uint64_t scans_rejected = 0;  // out of order, duplicate, bad time, refused by the profile
  std::uint64_t clock_restarts = 0;  // a sensor's clock restarted (batch_clock.hpp)
  std::uint64_t plots_processed = 0;
  std::uint64_t plots_invalid = 0;  // invalid_plot_reason
  std::uint64_t plots_rejected_clutter = 0;
  std::uint64_t numeric_failures = 0;  // ScanReport::numeric_failures
};

/// The reason name of a batch the profile cannot serve (dimension_refusal).
inline constexpr std::string_view kProfileRefusal = "rejected by the pipeline";

struct ScanResult {
  bool accepted = false;
  std::string rejection;          // why the batch was skipped, in full
  std::string_view reason;        // its short fixed name (batch_reason, kProfileRefusal)
  bool refused = false;           // skipped because the profile cannot serve these plots
  bool clock_restarted = false;   // its sensor's clock restarted (batch_clock.hpp)
  bool tracks_restarted = false;  // every track restarted on its time (sensor_timeline.hpp)
  TrackFrame frame;               // valid when accepted
  ScanReport report;
};

class Pipeline {
 public:
  static Expected<Pipeline> create(const config::TrackingProfile& profile);

  /// Processes one batch; never throws, whatever the input. Bad input is a rejection in the
  /// result; running out of memory (std::bad_alloc) terminates, by design (see process).
  const ScanResult& process(const PlotScan& scan) noexcept;

  const PipelineCounters& counters() const { return counters_; }
  const config::TrackingProfile& profile() const { return profile_; }
  /// New input limits for the next batches; the tracks go on.
  void set_input_limits(const config::InputLimitsSpec& limits);

 private:
  Pipeline(const config::TrackingProfile& profile,
           std::array<std::optional<EstimatorStages>, 2> built)
      : profile_(profile), built_(std::move(built)) {}
  /// Places the batch on the tracks' time (sensor_timeline.hpp): restarts its sensor's looks,
  /// or every track and look, as the placement says; false when the sensor is held.
  bool place_on_timeline(const PlotScan& scan, bool restarted, SensorFeed& feed);
  /// The batch itself when all its plots are usable, else a copy without the bad ones.
  const PlotScan& without_invalid_plots(const PlotScan& scan);

  config::TrackingProfile profile_;
  std::optional<EstimatorStages> stages_;  // taken or created with the first batch with plots
  // The stages of each dimension the first batch may choose (2-D, 3-D), built by create: the
  // first batch takes its own rather than building them in its scan time (the models, the
  // gates' quantiles). Emptied then; after a new timeline stages are built afresh.
  std::array<std::optional<EstimatorStages>, 2> built_;
  struct SensorState {
    BatchClock clock;
    SensorFeed feed;
  };
  std::map<std::uint32_t, SensorState> sensors_;
  SensorTimeline timeline_;
  PipelineCounters counters_;
  PlotScan clean_;  // a batch without its invalid plots, when it had some (reused)
  ScanResult result_;
};

/// What an accepted batch's clock restart or new timeline did to the tracks, for the log
/// (empty when nothing).
std::string timeline_change(const ScanResult& result);

/// The tracker dimension for a profile and the first batch: the profile's, or (auto) 3 when
/// the plots carry height (elevation, z, or a polar plot's flight level), else 2.
int tracker_dimension(const config::TrackingProfile& profile, const PlotScan& first);

/// Why a profile that asks for 3-D (dimension: 3) refuses a first batch whose plots carry no
/// height at all (no elevation, z or polar flight level): slant range and azimuth alone leave
/// the height unknown, and such tracks are useless. nullopt: served (or no plots to judge).
std::optional<std::string> dimension_refusal(const config::TrackingProfile& profile,
                                             const PlotScan& first);

/// Why a plot cannot be used, if so: a non-finite value, a negative range, a value beyond the
/// profile's input limits (range, angles, sigmas, its time from its batch's at `batch_time`).
std::optional<std::string> invalid_plot_reason(const Plot& plot,
                                               const config::InputLimitsSpec& limits,
                                               double batch_time);

}  // namespace skytrack
