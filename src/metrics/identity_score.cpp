#include "skytrack/metrics/identity_score.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "skytrack/core/transponder.hpp"

namespace skytrack::metrics {
namespace {

// A code change is the same aircraft: its new identity starts within this of where the old
// one ended, plus what an airliner flies meanwhile.
constexpr double kChangeDistance = 1000.0;  // [m]
constexpr double kChangeSpeed = 350.0;      // [m/s]
constexpr int kHeldForBreak = 3;            // plots of a segment a track must hold to count

bool generic_code(std::uint16_t code) {
  switch (code) {
    case 00000:
    case 01200:
    case 02000:
    case 07000:
    case 07500:
    case 07600:
    case 07700:
    case 07777:
      return true;
    default:
      return false;
  }
}

struct Segment {
  std::string identity;
  std::vector<std::size_t> plots;  // indices, in time order
};

/// Union-find over segments: identity chains.
struct Chains {
  std::vector<std::size_t> parent;
  explicit Chains(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t root(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  bool join(std::size_t a, std::size_t b) {
    a = root(a);
    b = root(b);
    if (a == b) return false;
    parent[std::max(a, b)] = std::min(a, b);
    return true;
  }
};

}  // namespace

std::string plot_identity(std::optional<std::uint16_t> mode3a,
                          std::optional<std::uint32_t> mode_s) {
  if (mode_s) return "S:" + format_mode_s(*mode_s);
  if (mode3a && !generic_code(*mode3a)) return "A:" + format_mode3a(*mode3a);
  return {};
}

IdentityScore score_identities(const std::vector<IdentityPlot>& plots,
                               const IdentityScoreConfig& config) {
  // Segments: each identity's plots in time order, split at gaps.
  std::map<std::string, std::vector<std::size_t>> by_identity;
  for (std::size_t i = 0; i < plots.size(); ++i) {
    if (!plots[i].identity.empty()) by_identity[plots[i].identity].push_back(i);
  }
  std::vector<Segment> segments;
  for (auto& [identity, list] : by_identity) {
    std::stable_sort(list.begin(), list.end(),
                     [&](std::size_t a, std::size_t b) { return plots[a].time < plots[b].time; });
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (k == 0 || plots[list[k]].time - plots[list[k - 1]].time > config.gap) {
        segments.push_back({identity, {}});
      }
      segments.back().plots.push_back(list[k]);
    }
  }
  std::sort(segments.begin(), segments.end(), [&](const Segment& a, const Segment& b) {
    return std::tie(plots[a.plots.front()].time, a.identity) <
           std::tie(plots[b.plots.front()].time, b.identity);
  });

  IdentityScore score;
  score.segments = static_cast<int>(segments.size());
  // Chains: one identity's segments, and code changes (an ending segment followed by the
  // nearest starting one of another identity, where it ended).
  Chains chains(segments.size());
  std::map<std::string, std::size_t> first_of;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    auto [it, fresh] = first_of.try_emplace(segments[s].identity, s);
    if (!fresh) chains.join(it->second, s);
  }
  std::vector<std::uint8_t> continued(segments.size(), 0);
  for (std::size_t a = 0; a < segments.size(); ++a) {
    const IdentityPlot& end = plots[segments[a].plots.back()];
    std::optional<std::size_t> best;
    double best_distance = 0.0;
    for (std::size_t b = 0; b < segments.size(); ++b) {
      if (continued[b] || segments[b].identity == segments[a].identity) continue;
      const IdentityPlot& start = plots[segments[b].plots.front()];
      const double dt = start.time - end.time;
      if (!(dt > 0.0 && dt <= config.gap)) continue;
      const double d = std::hypot(start.x - end.x, start.y - end.y);
      if (d > kChangeDistance + kChangeSpeed * dt) continue;
      if (!best || d < best_distance) {
        best = b;
        best_distance = d;
      }
    }
    if (best && chains.join(a, *best)) {
      continued[*best] = 1;
      ++score.code_changes;
    }
  }

  std::vector<IdentitySegment> described;
  std::map<std::int64_t, std::map<std::size_t, int>> held_by_track;  // track -> chain -> plots
  for (std::size_t s = 0; s < segments.size(); ++s) {
    IdentitySegment out;
    out.identity = segments[s].identity;
    out.first = plots[segments[s].plots.front()].time;
    out.last = plots[segments[s].plots.back()].time;
    out.min_range = out.max_range = plots[segments[s].plots.front()].range;
    std::map<std::int64_t, int> holders;
    for (const std::size_t i : segments[s].plots) {
      out.min_range = std::min(out.min_range, plots[i].range);
      out.max_range = std::max(out.max_range, plots[i].range);
      ++out.plots;
      if (!plots[i].track) continue;
      ++out.held;
      ++holders[*plots[i].track];
      ++held_by_track[*plots[i].track][chains.root(s)];
    }
    std::vector<std::pair<int, std::int64_t>> ranked;
    for (const auto& [track, n] : holders) {
      if (n >= kHeldForBreak) ranked.emplace_back(-n, track);
    }
    std::sort(ranked.begin(), ranked.end());
    for (const auto& [n, track] : ranked) out.tracks.push_back(track);
    out.breaks = std::max(0, static_cast<int>(out.tracks.size()) - 1);
    score.identity_plots += out.plots;
    score.held_plots += out.held;
    score.breaks += out.breaks;
    if (out.breaks > 0) ++score.segments_with_breaks;
    described.push_back(std::move(out));
  }
  int dominant = 0;
  for (const auto& [track, per_chain] : held_by_track) {
    int most = 0;
    for (const auto& [chain, n] : per_chain) most = std::max(most, n);
    dominant += most;
  }
  score.purity = score.held_plots > 0 ? static_cast<double>(dominant) / score.held_plots : 1.0;
  score.coverage =
      score.identity_plots > 0 ? static_cast<double>(score.held_plots) / score.identity_plots : 0.0;
  score.breaks_per_segment =
      score.segments > 0 ? static_cast<double>(score.breaks) / score.segments : 0.0;
  std::stable_sort(described.begin(), described.end(),
                   [](const IdentitySegment& a, const IdentitySegment& b) {
                     const int ua = a.plots - a.held, ub = b.plots - b.held;
                     return std::tie(b.breaks, ub) < std::tie(a.breaks, ua);
                   });
  described.resize(std::min(described.size(), config.worst));
  score.worst = std::move(described);
  return score;
}

}  // namespace skytrack::metrics
