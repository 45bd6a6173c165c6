// skytrack-fusion-mc: paper 004 §4 (track association through a merge and a split), Monte
// Carlo, printed as Markdown: per scan the fraction of runs with the right association and
// the mean number of system tracks, adaptive blend against the fixed one; then a summary.
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "experiment.hpp"

namespace {

using skytrack::fusion_mc::ScanTally;

constexpr double kEventTime = 20.0;  // [s] merge / split (paper §4)
constexpr double kFollowed = 0.95;   // fraction of runs right from which a change is followed

struct Summary {
  double error_before = 0.0, error_after = 0.0, targets_after = 0.0;
  double follow = -1.0;  // [s] after the event until >= kFollowed right to the end; -1 never
};

Summary summarise(const std::vector<ScanTally>& scans, int runs) {
  Summary s;
  int before = 0, after = 0;
  for (const ScanTally& t : scans) {
    const double wrong = 1.0 - static_cast<double>(t.correct) / runs;
    if (t.time < kEventTime) {
      s.error_before += wrong;
      ++before;
    } else {
      s.error_after += wrong;
      s.targets_after += static_cast<double>(t.system_tracks) / runs;
      ++after;
    }
  }
  s.error_before /= std::max(before, 1);
  s.error_after /= std::max(after, 1);
  s.targets_after /= std::max(after, 1);
  for (std::size_t i = scans.size(); i-- > 0;) {
    if (scans[i].time < kEventTime) break;
    if (static_cast<double>(scans[i].correct) / runs < kFollowed) break;
    s.follow = scans[i].time - kEventTime;
  }
  return s;
}

void report(const std::string& name, const std::vector<std::vector<ScanTally>>& r, int runs,
            std::uint64_t first_seed, bool per_scan, double alpha) {
  fmt::print("### Case {}: {} runs, seeds {}..{}, alpha = {:.2f} m\n\n", name, runs, first_seed,
             first_seed + static_cast<std::uint64_t>(runs) - 1, alpha);
  if (per_scan) {
    fmt::print("| t [s] | right, adaptive | right, fixed | targets, adaptive | targets, fixed |\n");
    fmt::print("|---:|---:|---:|---:|---:|\n");
    for (std::size_t i = 0; i < r[0].size(); ++i) {
      fmt::print("| {:.0f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} |\n", r[0][i].time,
                 static_cast<double>(r[0][i].correct) / runs,
                 static_cast<double>(r[1][i].correct) / runs,
                 static_cast<double>(r[0][i].system_tracks) / runs,
                 static_cast<double>(r[1][i].system_tracks) / runs);
    }
    fmt::print("\n");
  }
  fmt::print(
      "| blend | wrong before 20 s | wrong from 20 s | right (>= {:.0f} %) to the end from | "
      "mean targets from 20 s |\n|---|---:|---:|---:|---:|\n",
      100 * kFollowed);
  const char* names[2] = {"adaptive", "fixed 0.8 / 0.2"};
  for (int k = 0; k < 2; ++k) {
    const Summary s = summarise(r[static_cast<std::size_t>(k)], runs);
    const std::string follow = s.follow < 0 ? "never" : fmt::format("20 s + {:.0f} s", s.follow);
    fmt::print("| {} | {:.2f} % | {:.2f} % | {} | {:.2f} |\n", names[k], 100 * s.error_before,
               100 * s.error_after, follow, s.targets_after);
  }
  fmt::print("\n");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Paper 004 track association through a merge and a split (Monte Carlo)"};
  int runs = 100;
  std::uint64_t first_seed = 1001;
  std::string only;
  bool per_scan = false;
  double label_sigmas = skytrack::fusion::FusionSpec{}.label_penalty;
  app.add_option("--runs", runs, "Monte Carlo runs per case")->check(CLI::Range(1, 100000));
  app.add_option("--first-seed", first_seed, "Seed of the first run; run i uses it + i");
  app.add_option("--only", only, "One case only")
      ->check(CLI::IsMember({"merge", "split", "metric"}));
  app.add_flag("--per-scan", per_scan, "Print the per-scan table");
  app.add_option("--label-penalty", label_sigmas,
                 "alpha in pair sigmas (default: the shipped one; 0: no hysteresis)")
      ->check(CLI::Range(0.0, 9.0));
  CLI11_PARSE(app, argc, argv);
  using skytrack::fusion::Blend;
  namespace mc = skytrack::fusion_mc;
  const std::vector<skytrack::fusion::FusionSpec> specs{
      mc::paper_spec(Blend::kAdaptive, label_sigmas), mc::paper_spec(Blend::kFixed, label_sigmas)};
  try {
    if (only == "metric") {
      mc::run_metric_check(runs, first_seed);
      return 0;
    }
    for (const std::string name : {"merge", "split"}) {
      if (!only.empty() && only != name) continue;
      const auto truth = mc::load_truth(std::string(SKYTRACK_SOURCE_DIR) +
                                        "/config/scenarios/paper004_fusion_" + name + ".yaml");
      report(name, mc::run_monte_carlo(truth, specs, runs, first_seed), runs, first_seed, per_scan,
             specs[0].label_penalty);
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}\n", e.what());
    return 1;
  }
  return 0;
}
