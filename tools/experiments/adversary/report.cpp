#include "report.hpp"

#include <map>

#include <fmt/format.h>

#include "frame_comparison.hpp"
#include "measurements.hpp"

namespace skytrack::adversary {
namespace {

/// One phase's figures, computed from the run's records.
struct PhaseFigures {
  LatencySummary latency;
  StatusWindow status;
  std::size_t compared = 0, unchanged = 0;
};

/// Across all phases: the comparison's totals and its first differences.
struct Comparison {
  std::size_t compared = 0, unchanged = 0, numbers_differ = 0, with_adversary = 0;
  std::size_t max_adversary = 0;
  double max_deviation = 0.0;
  std::vector<std::string> differences;
};

std::string ms(double seconds) {
  return fmt::format("{:.1f}", seconds * 1e3);
}

std::string memory(const PhaseRecord& r, bool measured) {
  if (!measured) return "n/a (no --daemon-pid)";
  if (!r.last_memory) return "not sampled";
  return fmt::format("VmRSS max {:.1f} MiB, VmHWM {:.1f} MiB", r.rss_max_mib,
                     r.last_memory->hwm_mib);
}

class Reporter {
 public:
  explicit Reporter(const ReportInputs& in) : in_(in) {
    for (const ReceivedFrame& f : in.run.frames) frames_[f.frame.scan] = &f;
  }

  std::size_t print() {
    fmt::print("skytrack-adversary: sensor {} = {}\n", in_.good.sensor, in_.good.description);
    const auto& site = in_.geometry.site.position;
    fmt::print(
        "sensor {} (adversary) at ({:.1f}, {:.1f}) km, flooding azimuth [{:.2f}, {:.2f}] rad "
        "from north (its batches' coverage), clouds at {:.0f} km; rate {}x real time\n\n",
        in_.options.adversary_sensor, site.x() / 1e3, site.y() / 1e3, in_.geometry.sector.from,
        in_.geometry.sector.to, in_.geometry.cloud_range / 1e3, in_.options.rate);
    std::vector<PhaseFigures> figures;
    for (std::size_t p = 0; p < in_.run.phases.size(); ++p) {
      figures.push_back(figure(p));
      print_phase(p, figures.back());
    }
    print_table(figures);
    print_comparison();
    return comparison_.compared - comparison_.unchanged;
  }

 private:
  PhaseFigures figure(std::size_t p) {
    const PhaseRecord& r = in_.run.phases[p];
    PhaseFigures f;
    std::vector<double> latencies;
    std::size_t listed = 0;  // differences listed from this phase
    for (const std::size_t i : r.good) {
      const PlotScan& scan = in_.good.scans[i];
      const auto it = frames_.find(scan.scan);
      const ReceivedFrame* live = it == frames_.end() ? nullptr : it->second;
      if (live != nullptr && in_.run.written[i]) {
        latencies.push_back(std::chrono::duration<double>(live->at - *in_.run.written[i]).count());
      }
      const FrameVerdict v = compare_frames(live ? &live->frame : nullptr, in_.offline[i],
                                            in_.geometry, in_.options.tolerance);
      ++f.compared;
      f.unchanged += v.unchanged ? 1 : 0;
      note(v, scan, in_.phases[p], listed);
    }
    f.latency = summarize_latency(std::move(latencies), r.good.size());
    f.status = status_window(in_.run.statuses, r.begin, r.end);
    return f;
  }

  /// Adds a frame's verdict to the totals; lists its difference while the phase has listed
  /// fewer than kPerPhase and the whole list is shorter than --differences.
  void note(const FrameVerdict& v, const PlotScan& scan, const Phase& phase, std::size_t& listed) {
    constexpr std::size_t kPerPhase = 3;
    Comparison& c = comparison_;
    ++c.compared;
    c.with_adversary += v.adversary > 0 ? 1 : 0;
    c.max_adversary = std::max(c.max_adversary, v.adversary);
    if (v.unchanged) {
      ++c.unchanged;
      c.numbers_differ += v.numbers_differ ? 1 : 0;
      c.max_deviation = std::max(c.max_deviation, v.max_deviation);
    } else if (listed < kPerPhase &&
               c.differences.size() < static_cast<std::size_t>(in_.options.differences)) {
      ++listed;
      c.differences.push_back(fmt::format("scan {} (t = {:.2f} s, phase {}): {}", scan.scan,
                                          scan.time, phase.name, v.difference));
    }
  }

  void print_phase(std::size_t p, const PhaseFigures& f) const {
    const Phase& phase = in_.phases[p];
    const PhaseRecord& r = in_.run.phases[p];
    const PhaseTally& t = r.tally;
    fmt::print("== phase {}/{}: {} (stream {:.0f}-{:.0f} s): {}\n", p + 1, in_.phases.size(),
               phase.name, phase.begin - in_.good.start, phase.end - in_.good.start, phase.what);
    fmt::print(
        "  sensor {} sent: {} batches, {} plots, {} malformed; {} write errors{}; {} ms "
        "writing\n",
        in_.options.adversary_sensor, t.batches, t.plots, t.malformed, t.write_errors,
        t.first_error.empty() ? "" : " (" + t.first_error + ")", ms(t.write_seconds));
    fmt::print("  sensor {} latency: {} batches, {} answered: p50 {} ms, p99 {} ms, max {} ms\n",
               in_.good.sensor, f.latency.sent, f.latency.answered, ms(f.latency.p50),
               ms(f.latency.p99), ms(f.latency.max));
    const StatusWindow& s = f.status;
    fmt::print(
        "  skytrackd status: {}scans processed {}, plots {}, scans_dropped {}, queue depth "
        "max {}, confirmed tracks {}\n",
        s.seen ? "" : "(none received) ", s.scans_processed, s.plots_processed, s.scans_dropped,
        s.queue_max, s.confirmed);
    fmt::print("    scans rejected: {}\n    plots rejected: {}\n", format_counts(s.scans_rejected),
               format_counts(s.plots_rejected));
    fmt::print("  skytrackd memory: {}\n", memory(r, in_.options.daemon_pid > 0));
    fmt::print("  sensor {} frames unchanged: {} / {}\n\n", in_.good.sensor, f.unchanged,
               f.compared);
  }

  void print_table(const std::vector<PhaseFigures>& figures) const {
    fmt::print("== summary\n");
    fmt::print(
        "{:<16} {:>8} {:>8} | {:>23} {:>6} | {:>7} {:>7} {:>7} {:>5} | {:>9} {:>9} | {:>9}\n",
        "phase", "s2 batch", "s2 plots", "s1 latency p50/p99/max", "unans.", "scans", "plots",
        "dropped", "queue", "VmRSS max", "VmHWM", "s1 frames");
    fmt::print(
        "{:<16} {:>8} {:>8} | {:>23} {:>6} | {:>7} {:>7} {:>7} {:>5} | {:>9} {:>9} | {:>9}\n", "",
        "", "", "[ms]", "", "rejected", "rejected", "", "max", "[MiB]", "[MiB]", "unchanged");
    for (std::size_t p = 0; p < figures.size(); ++p) {
      const PhaseFigures& f = figures[p];
      const PhaseRecord& r = in_.run.phases[p];
      std::uint64_t scans = 0, plots = 0;
      for (const auto& [reason, n] : f.status.scans_rejected) scans += n;
      for (const auto& [reason, n] : f.status.plots_rejected) plots += n;
      const bool mem = r.last_memory.has_value();
      fmt::print(
          "{:<16} {:>8} {:>8} | {:>23} {:>6} | {:>7} {:>8} {:>7} {:>5} | {:>9} {:>9} | {:>9}\n",
          in_.phases[p].name, r.tally.batches, r.tally.plots,
          fmt::format("{}/{}/{}", ms(f.latency.p50), ms(f.latency.p99), ms(f.latency.max)),
          f.latency.sent - f.latency.answered, scans, plots, f.status.scans_dropped,
          f.status.queue_max, mem ? fmt::format("{:.1f}", r.rss_max_mib) : "n/a",
          mem ? fmt::format("{:.1f}", r.last_memory->hwm_mib) : "n/a",
          fmt::format("{}/{}", f.unchanged, f.compared));
    }
    fmt::print("\n");
  }

  void print_comparison() const {
    const Comparison& c = comparison_;
    const std::uint32_t s1 = in_.good.sensor;
    fmt::print(
        "sensor {} frames unchanged: {} / {} (against an offline Pipeline run of sensor {} alone: "
        "firm tracks outside sensor {}'s sector widened by {} rad, matched one to one by "
        "position within {} m, same status; largest deviation in an unchanged frame {:.3g} m)\n",
        s1, c.unchanged, c.compared, s1, in_.options.adversary_sensor, kSectorMargin,
        in_.options.tolerance, c.max_deviation);
    fmt::print(
        "track numbers: {} (numbers come from one counter at confirmation, so they may "
        "legitimately differ once sensor {} gets a track confirmed); frames holding sensor {} "
        "firm tracks: {} (at most {} at once)\n",
        c.numbers_differ == 0
            ? std::string("the same in every unchanged frame")
            : fmt::format("differ in {} of the unchanged frames", c.numbers_differ),
        in_.options.adversary_sensor, in_.options.adversary_sensor, c.with_adversary,
        c.max_adversary);
    if (!c.differences.empty()) {
      fmt::print("first differences (at most 3 per phase):\n");
      for (const std::string& d : c.differences) fmt::print("  {}\n", d);
    }
    std::uint64_t other = 0;
    for (const PhaseRecord& r : in_.run.phases) other += r.tally.batches;
    fmt::print(
        "run: {:.1f} s, {} sensor {} batches written, {} sensor {} batches and samples; {}\n",
        in_.run.wall_seconds, in_.run.writes, s1, other, in_.options.adversary_sensor,
        in_.run.stopped.empty() ? "completed" : "stopped early: " + in_.run.stopped);
  }

  const ReportInputs& in_;
  std::map<std::uint64_t, const ReceivedFrame*> frames_;
  Comparison comparison_;
};

}  // namespace

std::size_t print_report(const ReportInputs& in) {
  return Reporter(in).print();
}

}  // namespace skytrack::adversary
