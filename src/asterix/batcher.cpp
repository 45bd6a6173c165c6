#include "skytrack/asterix/batcher.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace skytrack::asterix {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kJitter = 0.5;  // [rad] a plot this far behind the antenna is late, not a turn on

Plot to_plot(const TargetReport& r) {
  Plot p;
  p.form = PlotForm::kPolar;
  p.time = r.time;
  p.range = r.range;
  p.azimuth = r.azimuth;
  p.mode3a = r.mode3a;
  p.mode_s = r.mode_s;
  p.flight_level = r.flight_level;
  return p;
}

bool sector_message(ServiceKind kind) {
  return kind == ServiceKind::kNorthMarker || kind == ServiceKind::kSectorCrossing ||
         kind == ServiceKind::kSouthMarker;
}

}  // namespace

Expected<BatchOptions> parse_batch_mode(const std::string& text) {
  BatchOptions o;
  if (text == "sector") return o;
  if (text == "revolution") {
    o.mode = BatchMode::kRevolution;
    return o;
  }
  if (text.rfind("block:", 0) == 0) {
    const std::string n = text.substr(6);
    if (!n.empty() && n.size() < 8 && n.find_first_not_of("0123456789") == std::string::npos &&
        std::stoul(n) >= 1) {
      o.mode = BatchMode::kBlock;
      o.block_plots = std::stoul(n);
      return o;
    }
  }
  return make_error("--batch: expected sector, revolution or block:N (N >= 1), got '" + text + "'");
}

std::string to_string(const BatchOptions& o) {
  switch (o.mode) {
    case BatchMode::kRevolution:
      return "revolution";
    case BatchMode::kBlock:
      return "block:" + std::to_string(o.block_plots);
    case BatchMode::kSector:
      break;
  }
  return "sector";
}

struct Batcher::SensorState {
  std::uint32_t sensor = 0;
  std::uint64_t next_scan = 0;
  double last_time = -std::numeric_limits<double>::infinity();  // of the last batch
  std::vector<Plot> plots;                                      // the open batch
  std::vector<double> unwrapped;    // revolution mode: parallel to plots
  std::optional<double> reference;  // sector mode: first plot or last marker [s]
  bool markers = false;
  std::optional<double> marker_azimuth;
  // Revolution mode.
  bool by_revolution = false;
  double turn = 0.0;          // revolution index of the open batch
  std::vector<Plot> pending;  // already past north, less than `lead`
  std::vector<double> pending_unwrapped;
  std::optional<double> last_u, last_t;  // the most advanced plot so far
  std::optional<double> sent_period, fitted_period;
  // Sector mode: the batch a sector message closed, held until a plot measured after the
  // message arrives: radars send the plots of a sector's last cells after its message.
  std::optional<PlotScan> held;

  std::optional<double> period() const { return sent_period ? sent_period : fitted_period; }
  double latest_plot_time() const {
    double t = last_time;
    for (const Plot& p : plots) t = std::max(t, *p.time);
    return t;
  }
};

Batcher::Batcher(BatchOptions options, ScanSink sink) : options_(options), sink_(std::move(sink)) {}
Batcher::~Batcher() = default;
Batcher::Batcher(Batcher&&) noexcept = default;
Batcher& Batcher::operator=(Batcher&&) noexcept = default;

Batcher::SensorState& Batcher::state(std::uint32_t sensor) {
  for (SensorState& s : sensors_) {
    if (s.sensor == sensor) return s;
  }
  SensorState& s = sensors_.emplace_back();
  s.sensor = sensor;
  s.by_revolution = options_.mode == BatchMode::kRevolution;
  return s;
}

std::optional<double> Batcher::rotation_period(std::uint32_t sensor) const {
  for (const SensorState& s : sensors_) {
    if (s.sensor == sensor) return s.period();
  }
  return std::nullopt;
}

bool Batcher::late_for(const SensorState& s, const TargetReport& report) const {
  // Behind the message's azimuth by less than a quarter turn, and measured by its time: the
  // antenna had swept it before the message (the time resolution alone, 1/128 s, cannot tell).
  double behind = std::fmod(*s.marker_azimuth - report.azimuth, kTwoPi);
  if (behind < 0.0) behind += kTwoPi;
  return behind > 0.0 && behind < kTwoPi / 4 && report.time <= s.held->time + options_.late;
}

void Batcher::release(SensorState& s) {
  if (!s.held) return;
  PlotScan scan = std::move(*s.held);
  s.held.reset();
  for (std::size_t i = 0; i < scan.plots.size(); ++i) {
    scan.plots[i].id = static_cast<std::int64_t>(i);
  }
  ++batches_;
  sink_(std::move(scan));
}

void Batcher::close(SensorState& s, double time, std::optional<AzimuthSector> coverage, bool hold) {
  release(s);
  // A batch needs a time: a sector message without one, before any plot or batch of its
  // sensor, has nothing to time it by (found by fuzzing).
  if (!std::isfinite(time)) time = s.latest_plot_time();
  if (!std::isfinite(time)) {
    s.plots.clear();
    s.unwrapped.clear();
    return;
  }
  PlotScan scan;
  scan.sensor = s.sensor;
  scan.scan = s.next_scan++;
  scan.time = std::max(time, s.last_time);
  s.last_time = scan.time;
  scan.coverage = coverage;
  scan.plots = std::move(s.plots);
  s.plots.clear();
  s.unwrapped.clear();
  s.held = std::move(scan);
  if (!hold) release(s);
}

void Batcher::close_revolution(SensorState& s, std::optional<double> next_time) {
  // The rotation period from a least-squares line u = u0 + w t through the batch's plots, when
  // they spread over a quarter turn at least (a few aircraft at one azimuth say nothing of it);
  // the north crossing from the most advanced plot and the period (sent, else fitted).
  const std::size_t n = s.plots.size();
  double tm = 0.0, um = 0.0, latest = s.last_time, u_min = 0.0, u_max = 0.0, t_max = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    tm += *s.plots[i].time;
    um += s.unwrapped[i];
    latest = std::max(latest, *s.plots[i].time);
    if (i == 0 || s.unwrapped[i] < u_min) u_min = s.unwrapped[i];
    if (i == 0 || s.unwrapped[i] > u_max) u_max = s.unwrapped[i], t_max = *s.plots[i].time;
  }
  if (n >= 3 && u_max - u_min >= kTwoPi / 4) {
    tm /= static_cast<double>(n);
    um /= static_cast<double>(n);
    double stt = 0.0, stu = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double dt = *s.plots[i].time - tm;
      stt += dt * dt;
      stu += dt * (s.unwrapped[i] - um);
    }
    const double w = stt > 0.0 ? stu / stt : 0.0;
    if (w > kTwoPi / 60.0 && w < kTwoPi / 0.5) {
      const double period = kTwoPi / w;
      s.fitted_period = s.fitted_period ? 0.8 * *s.fitted_period + 0.2 * period : period;
    }
  }
  double crossing = latest;
  if (const auto period = s.period(); period && n > 0) {
    crossing = t_max + (kTwoPi * (s.turn + 1.0) - u_max) * *period / kTwoPi;
  }
  crossing = std::max(crossing, latest);
  for (const Plot& p : s.pending) crossing = std::min(crossing, *p.time);
  if (next_time) crossing = std::min(crossing, *next_time);
  close(s, std::max(crossing, latest), std::nullopt);
  s.plots = std::move(s.pending);
  s.unwrapped = std::move(s.pending_unwrapped);
  s.pending.clear();
  s.pending_unwrapped.clear();
  s.turn += 1.0;
}

void Batcher::add_revolution(SensorState& s, Plot plot) {
  const double t = *plot.time;
  const std::optional<double> period = s.period();
  if (s.last_t && t - *s.last_t > 1.5 * period.value_or(30.0)) {
    // A silence longer than a turn: the azimuths cannot be unwrapped across it.
    close_revolution(s, t);
    if (!s.plots.empty()) close(s, s.latest_plot_time(), std::nullopt);
    s.last_u.reset();
    s.last_t.reset();
  }
  double u = plot.azimuth;
  if (!s.last_u) {
    s.turn = 0.0;
  } else if (period) {
    const double predicted = *s.last_u + kTwoPi * (t - *s.last_t) / *period;
    u += kTwoPi * std::round((predicted - u) / kTwoPi);
  } else {
    u += kTwoPi * std::ceil((*s.last_u - kJitter - u) / kTwoPi);
  }
  if (!s.last_u || u > *s.last_u) {
    s.last_u = u;
    s.last_t = t;
  }
  const double turn = std::floor(u / kTwoPi);
  if (turn <= s.turn) {
    s.plots.push_back(std::move(plot));
    s.unwrapped.push_back(u);
  } else if (turn == s.turn + 1.0 && u < kTwoPi * turn + options_.lead) {
    s.pending.push_back(std::move(plot));
    s.pending_unwrapped.push_back(u);
  } else {
    close_revolution(s, t);
    s.turn = turn;
    s.plots.push_back(std::move(plot));
    s.unwrapped.push_back(u);
  }
}

void Batcher::add(const TargetReport& report) {
  SensorState& s = state(report.sensor);
  Plot plot = to_plot(report);
  if (options_.mode == BatchMode::kBlock) {
    s.plots.push_back(std::move(plot));
    if (s.plots.size() >= options_.block_plots) close(s, s.latest_plot_time(), std::nullopt);
    return;
  }
  if (s.by_revolution) return add_revolution(s, std::move(plot));
  if (s.held) {
    if (late_for(s, report)) return s.held->plots.push_back(std::move(plot));
    if (report.time > s.held->time + options_.late) release(s);
  }
  if (!s.reference) s.reference = report.time;
  s.plots.push_back(std::move(plot));
  if (report.time - *s.reference > options_.marker_wait) {
    // No sector message for too long: batch this sensor by revolution until one comes.
    s.by_revolution = true;
    std::vector<Plot> held = std::move(s.plots);
    s.plots.clear();
    for (Plot& p : held) add_revolution(s, std::move(p));
  }
}

void Batcher::add(const ServiceMessage& message) {
  SensorState& s = state(message.sensor);
  if (message.rotation_period) s.sent_period = message.rotation_period;
  if (options_.mode != BatchMode::kSector || !sector_message(message.kind) || !message.azimuth) {
    return;
  }
  const double time = message.time.value_or(s.latest_plot_time());
  if (s.by_revolution) {  // sector messages are back: what was held closes here
    for (std::size_t i = 0; i < s.pending.size(); ++i) s.plots.push_back(std::move(s.pending[i]));
    s.pending.clear();
    s.pending_unwrapped.clear();
    s.last_u.reset();
    s.last_t.reset();
    s.by_revolution = false;
    if (!s.plots.empty()) close(s, time, std::nullopt);
  } else if (s.marker_azimuth) {
    std::optional<AzimuthSector> coverage = AzimuthSector{*s.marker_azimuth, *message.azimuth};
    if (std::abs(coverage->from - coverage->to) < 1e-9) coverage.reset();  // a whole turn
    close(s, time, coverage, true);
  } else if (!s.plots.empty()) {
    close(s, time, std::nullopt, true);  // the first batch: where the sweep began is unknown
  }
  s.markers = true;
  s.marker_azimuth = *message.azimuth;
  s.reference.reset();  // the marker wait counts from the next plot
  if (std::isfinite(time)) s.reference = time;
}

void Batcher::finish() {
  for (SensorState& s : sensors_) {
    release(s);
    if (s.by_revolution && !s.plots.empty()) close_revolution(s, std::nullopt);
    for (std::size_t i = 0; i < s.pending.size(); ++i) s.plots.push_back(std::move(s.pending[i]));
    s.pending.clear();
    s.pending_unwrapped.clear();
    if (!s.plots.empty()) close(s, s.latest_plot_time(), std::nullopt);
  }
}

}  // namespace skytrack::asterix
