#include "eval_identity.hpp"

#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "skytrack/geometry/frames.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/metrics/identity_score.hpp"

namespace skytrack::tool {
namespace {

using PlotKey = std::tuple<std::uint32_t, std::uint64_t, std::int64_t>;  // sensor, scan, id

void print_rejected(const io::LineError& error) {
  fmt::print(stderr, "{}\n", io::to_string(error));
}

std::string json(const metrics::IdentityScore& s, const IdentityOptions& o) {
  std::string out = fmt::format(
      "{{\"segments\": {}, \"breaks\": {}, \"breaks_per_segment\": {}, "
      "\"segments_with_breaks\": {}, \"purity\": {}, \"coverage\": {}, \"identity_plots\": {}, "
      "\"held_plots\": {}, \"code_changes\": {}, \"gap\": {}, \"worst\": [",
      s.segments, s.breaks, s.breaks_per_segment, s.segments_with_breaks, s.purity, s.coverage,
      s.identity_plots, s.held_plots, s.code_changes, o.gap);
  for (std::size_t i = 0; i < s.worst.size(); ++i) {
    const metrics::IdentitySegment& w = s.worst[i];
    out += fmt::format(
        "{}{{\"identity\": \"{}\", \"first\": {}, \"last\": {}, \"min_range\": {}, "
        "\"max_range\": {}, \"plots\": {}, \"held\": {}, \"breaks\": {}, \"tracks\": [{}]}}",
        i == 0 ? "" : ", ", w.identity, w.first, w.last, w.min_range, w.max_range, w.plots, w.held,
        w.breaks, fmt::join(w.tracks, ", "));
  }
  return out + "]}";
}

void table(const metrics::IdentityScore& s, const IdentityOptions& o) {
  fmt::print("skytrack eval --identity: {} identity plots in {} segments (gap {} s)\n",
             s.identity_plots, s.segments, o.gap);
  fmt::print("  {:<24}{} ({:.4f} per segment), {} segments with breaks\n", "breaks", s.breaks,
             s.breaks_per_segment, s.segments_with_breaks);
  fmt::print("  {:<24}{:.4f}\n", "purity", s.purity);
  fmt::print("  {:<24}{:.4f} ({} of {} plots held)\n", "coverage", s.coverage, s.held_plots,
             s.identity_plots);
  fmt::print("  {:<24}{}\n", "code changes linked", s.code_changes);
  if (s.worst.empty()) return;
  fmt::print("\n  {:<10} {:>9} {:>9} {:>8} {:>8} {:>6} {:>6} {:>6}  tracks\n", "identity",
             "first [s]", "last [s]", "rmin[km]", "rmax[km]", "plots", "held", "breaks");
  for (const metrics::IdentitySegment& w : s.worst) {
    fmt::print("  {:<10} {:>9.1f} {:>9.1f} {:>8.1f} {:>8.1f} {:>6} {:>6} {:>6}  {}\n", w.identity,
               w.first, w.last, w.min_range / 1000.0, w.max_range / 1000.0, w.plots, w.held,
               w.breaks, fmt::join(w.tracks, " "));
  }
}

}  // namespace

int run_eval_identity(const IdentityOptions& options) {
  auto plot_reader = io::PlotStreamReader::open(options.plots_path, print_rejected);
  if (!plot_reader) {
    fmt::print(stderr, "skytrack eval: {}\n", plot_reader.error().message);
    return 2;
  }
  auto track_reader = io::TrackReader::open(options.tracks_path, print_rejected);
  if (!track_reader) {
    fmt::print(stderr, "skytrack eval: {}\n", track_reader.error().message);
    return 2;
  }
  std::vector<metrics::IdentityPlot> plots;
  std::map<PlotKey, std::size_t> index;
  while (std::optional<PlotScan> scan = plot_reader->next()) {
    for (const Plot& plot : scan->plots) {
      const Eigen::Vector3d p = plot_position_enu(plot, scan->platform);
      index[{scan->sensor, scan->scan, plot.id}] = plots.size();
      plots.push_back({plot_time(plot, *scan), metrics::plot_identity(plot.mode3a, plot.mode_s),
                       p.x(), p.y(), (p - scan->platform.position).norm(), std::nullopt});
    }
  }
  if (plot_reader->read_error()) {
    fmt::print(stderr, "skytrack eval: {}\n", *plot_reader->read_error());
    return 2;
  }
  // Each plot's track: the confirmed or coasting one likeliest to hold it in its batch.
  std::map<PlotKey, double> best;
  std::size_t unknown = 0;
  while (std::optional<TrackFrame> frame = track_reader->next()) {
    std::map<std::int64_t, TrackStatus> status;
    for (const TrackReport& t : frame->tracks) status[t.id] = t.status;
    for (const Association& a : frame->associations) {
      const auto s = status.find(a.track);
      if (s == status.end() || !is_reported_as_firm(s->second)) continue;
      const PlotKey key{frame->sensor, a.scan.value_or(frame->scan), a.plot};
      const auto at = index.find(key);
      if (at == index.end()) {
        ++unknown;
        continue;
      }
      auto [it, fresh] = best.try_emplace(key, a.probability);
      if (!fresh && a.probability <= it->second) continue;
      it->second = a.probability;
      plots[at->second].track = a.track;
    }
  }
  if (track_reader->read_error()) {
    fmt::print(stderr, "skytrack eval: {}\n", *track_reader->read_error());
    return 2;
  }
  if (unknown > 0) {
    fmt::print(stderr, "skytrack eval: {} associations name no plot of {}\n", unknown,
               options.plots_path);
  }
  const metrics::IdentityScore score = metrics::score_identities(plots, {.gap = options.gap});
  if (options.json) {
    fmt::print("{}\n", json(score, options));
  } else {
    table(score, options);
  }
  return 0;
}

}  // namespace skytrack::tool
