#pragma once
// The false-plot density each plot of a look is weighed against (JPDA, existence): plots of
// one measurement form spread over the box they span in measurement space (their count over
// its volume; targets add a few plots, which only makes it slightly conservative), raised by
// the clutter map where clutter is locally denser (clutter_map.hpp).
//
// A look of a rotating antenna may be a sector or a few plots; its density is estimated over
// the plots of the last revolution of sweep (its own and the earlier looks' of the same
// sensor), so that it does not depend on how the feed batched them. A snapshot look (or a
// whole revolution) is estimated from its own plots alone.
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "skytrack/clutter/clutter_map.hpp"
#include "skytrack/measurement/plot_measurement.hpp"

namespace skytrack::clutter {

class ClutterDensity {
 public:
  /// `map`: the clutter map's cells; none: no clutter map.
  explicit ClutterDensity(std::optional<ClutterMapCells> map);

  /// Per plot of the look, its density in its measurement space, or 0 where a form has too few
  /// plots to say (the caller's fallback applies). The box counts the `boxed` plots (not the
  /// rejected ones, nor a plot cloud's, which is local clutter and no measure of the sky);
  /// the map counts the `counted` ones (the plots no firm track gates: the false ones).
  /// `windowed`: the look is part of a rotating antenna's revolution (plots carry their
  /// sweep).
  void estimate(std::uint32_t sensor, bool windowed, std::span<const PlotMeasurement> plots,
                std::span<const std::uint8_t> boxed, std::span<const std::uint8_t> counted,
                std::vector<double>& density);

  /// Keeps a windowed look's plots (all but the rejected) for the looks that follow.
  void remember(std::uint32_t sensor, std::span<const PlotMeasurement> plots,
                std::span<const std::uint8_t> rejected, std::span<const std::uint8_t> boxed,
                std::span<const std::uint8_t> counted);

 private:
  struct Seen {
    PlotMeasurement plot;
    std::uint8_t counted = 0;
    std::uint8_t boxed = 1;
  };
  /// Drops what lies a revolution or more before `latest`.
  void forget(std::vector<Seen>& window, double latest) const;

  bool map_enabled_ = false;
  ClutterMapCells cells_;
  std::map<std::uint32_t, std::vector<Seen>> windows_;  // per sensor, oldest first
  // Workspaces (reused).
  std::vector<PlotMeasurement> all_;
  std::vector<std::uint8_t> all_counted_, all_used_;
  std::vector<double> all_density_;
};

}  // namespace skytrack::clutter
