// skytrack-group-mc: paper 000's experiments (§4.1, §4.2), Monte Carlo, printed as Markdown.
#include <algorithm>
//   exp1: LBP-PHD against BP-PHD and MS-BP-PHD (k-means extraction): mean OSPA (p = 2,
//         c = 500 m) and group count per scan, run time per run; optional SVG of one run.
//   exp2: double against single label through missed group detections (P_d = 0.98).
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "bp_phd_kmeans.hpp"
#include "run_record.hpp"
#include "scenario.hpp"
#include "skytrack/group/group_tracker.hpp"
#include "skytrack/metrics/ospa_gospa.hpp"
#include "svg_writer.hpp"

namespace group_mc {
namespace {

using skytrack::group::GroupSpec;
using Clock = std::chrono::steady_clock;
constexpr double kPartitionDistance = 15.0;  // [m] BP-PHD's distance partitioning
constexpr int kFilters = 5;
constexpr const char* kNames[kFilters] = {"LBP-PHD", "MS-BP-PHD", "BP-PHD", "MS-BP-PHD k-means++",
                                          "BP-PHD k-means++"};

RunRecord run_lbp(const Scenario& sc, const GroupSpec& spec) {
  RunRecord r;
  r.scans.resize(sc.scans.size());
  skytrack::group::GroupTracker tracker(spec);
  const auto t0 = Clock::now();
  for (std::size_t k = 0; k < sc.scans.size(); ++k) {
    const auto& est = tracker.process(sc.scans[k].time, std::span(sc.scans[k].plots));
    ScanEstimates& s = r.scans[k];
    s.group_count = tracker.filter().group_count();
    for (const auto& e : est) {
      if (e.missed_scans == 0) {
        s.positions.push_back(e.position);
        s.labels.push_back(e.label);
      }
    }
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

RunRecord run_baseline(const Scenario& sc, const GroupSpec& spec, bool mean_shift,
                       KmeansInit init) {
  RunRecord r;
  r.scans.resize(sc.scans.size());
  BpPhdKmeans filter(spec, mean_shift, kPartitionDistance, init);
  const auto t0 = Clock::now();
  for (std::size_t k = 0; k < sc.scans.size(); ++k) {
    const auto& est = filter.step(sc.scans[k].time, sc.scans[k].plots);
    ScanEstimates& s = r.scans[k];
    s.group_count = filter.group_count();
    for (const auto& e : est) {
      s.positions.push_back(Eigen::Vector2d(e(0), e(2)));
      s.labels.push_back(0);
    }
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

struct Totals {
  std::vector<double> ospa, count;  // sums per scan
  std::vector<int> count_right;     // runs with the right count per scan
  double seconds = 0.0;
};

void accumulate(const Scenario& sc, const RunRecord& r, Totals& t) {
  const std::size_t n = sc.scans.size();
  t.ospa.resize(n, 0.0);
  t.count.resize(n, 0.0);
  t.count_right.resize(n, 0);
  skytrack::metrics::OspaGospa metric({500.0, 2.0});
  for (std::size_t k = 0; k < n; ++k) {
    const auto truth = sc.truth_positions(static_cast<int>(k) + 1);
    t.ospa[k] += metric.compute(truth, r.scans[k].positions).ospa;
    t.count[k] += static_cast<double>(r.scans[k].positions.size());
    t.count_right[k] += r.scans[k].positions.size() == truth.size() ? 1 : 0;
  }
  t.seconds += r.seconds;
}

int experiment1(int runs, std::uint64_t first_seed, const std::string& svg) {
  GroupSpec spec;  // the paper's exp. 1 defaults
  Totals totals[kFilters];
  Scenario first;
  for (int run = 0; run < runs; ++run) {
    const std::uint64_t seed = first_seed + static_cast<std::uint64_t>(run);
    const Scenario sc = make_experiment1(seed);
    spec.seed = seed;
    const RunRecord a = run_lbp(sc, spec);
    accumulate(sc, a, totals[0]);
    accumulate(sc, run_baseline(sc, spec, true, KmeansInit::kRandom), totals[1]);
    accumulate(sc, run_baseline(sc, spec, false, KmeansInit::kRandom), totals[2]);
    accumulate(sc, run_baseline(sc, spec, true, KmeansInit::kPlusPlus), totals[3]);
    accumulate(sc, run_baseline(sc, spec, false, KmeansInit::kPlusPlus), totals[4]);
    if (run == 0 && !svg.empty() && !write_svg(svg, sc, a)) {
      std::fprintf(stderr, "cannot write %s\n", svg.c_str());
      return 1;
    }
    if (run == 0) {
      first = sc;
    }
  }
  const double n = runs;
  fmt::print("## Experiment 1: {} runs, seeds {}..{}\n\n", runs, first_seed,
             first_seed + static_cast<std::uint64_t>(runs) - 1);
  fmt::print(
      "Mean over the runs per scan: estimated group count and OSPA (p = 2, c = 500 m) "
      "[m]; k-means seeded at random boxes unless marked k-means++.\n\n");
  fmt::print("| scan | groups |");
  for (const char* name : kNames) {
    fmt::print(" {} count |", name);
  }
  for (const char* name : kNames) {
    fmt::print(" {} OSPA |", name);
  }
  fmt::print(" LBP count right |\n|---|---|");
  for (int f = 0; f < 2 * kFilters + 1; ++f) {
    fmt::print("---|");
  }
  fmt::print("\n");
  const std::vector<int> birth_first = {1, 15, 20, 25};
  const auto is_birth_first = [&](std::size_t k) {
    return std::find(birth_first.begin(), birth_first.end(), static_cast<int>(k) + 1) !=
           birth_first.end();
  };
  double many[kFilters] = {}, all[kFilters] = {}, settled[kFilters] = {};
  int many_scans = 0, settled_scans = 0, scored = 0;
  const std::size_t scans = totals[0].ospa.size();
  for (std::size_t k = 0; k < scans; ++k) {
    const int truth = static_cast<int>(first.truth_positions(static_cast<int>(k) + 1).size());
    fmt::print("| {} | {} |", k + 1, truth);
    for (const Totals& t : totals) {
      fmt::print(" {:.2f} |", t.count[k] / n);
    }
    for (int f = 0; f < kFilters; ++f) {
      fmt::print(" {:.1f} |", totals[f].ospa[k] / n);
      all[f] += totals[f].ospa[k] / n;
      many[f] += truth >= 4 ? totals[f].ospa[k] / n : 0.0;
      settled[f] += truth >= 4 && !is_birth_first(k) ? totals[f].ospa[k] / n : 0.0;
    }
    settled_scans += truth >= 4 && !is_birth_first(k) ? 1 : 0;
    fmt::print(" {:.0f} % |\n", 100.0 * totals[0].count_right[k] / n);
    many_scans += truth >= 4 ? 1 : 0;
    if (std::find(birth_first.begin(), birth_first.end(), static_cast<int>(k) + 1) ==
        birth_first.end()) {
      scored += runs;
    }
  }
  fmt::print(
      "\n| filter | mean OSPA, the {} scans with >= 4 groups [m] | the same without births' "
      "first scans ({}) [m] | mean OSPA, all scans [m] | group count right (scans but each "
      "birth's first) | mean run time per run [ms] |\n|---|---|---|---|---|---|\n",
      many_scans, settled_scans);
  for (int f = 0; f < kFilters; ++f) {
    int ok = 0;
    for (std::size_t k = 0; k < scans; ++k) {
      if (std::find(birth_first.begin(), birth_first.end(), static_cast<int>(k) + 1) ==
          birth_first.end()) {
        ok += totals[f].count_right[k];
      }
    }
    fmt::print("| {} | {:.1f} | {:.1f} | {:.1f} | {:.1f} % | {:.2f} |\n", kNames[f],
               many[f] / many_scans, settled[f] / std::max(settled_scans, 1),
               all[f] / static_cast<double>(scans), 100.0 * ok / std::max(scored, 1),
               1e3 * totals[f].seconds / n);
  }
  fmt::print("\nBirths' first scans (not scored for the count): k = 1, 15, 20, 25.\n");
  return 0;
}

}  // namespace

int experiment2(int runs, std::uint64_t first_seed);

}  // namespace group_mc

int main(int argc, char** argv) {
  CLI::App app{"Paper 000 (LBP-PHD group tracking) experiments, Monte Carlo"};
  std::string experiment = "exp1";
  int runs = 100;
  std::uint64_t first_seed = 1;
  std::string svg;
  app.add_option("experiment", experiment, "exp1 or exp2")->check(CLI::IsMember({"exp1", "exp2"}));
  app.add_option("--runs", runs, "Monte Carlo runs")->check(CLI::PositiveNumber);
  app.add_option("--first-seed", first_seed, "seed of the first run (then +1 per run)");
  app.add_option("--svg", svg, "exp1: SVG picture of the first run");
  CLI11_PARSE(app, argc, argv);
  return experiment == "exp1" ? group_mc::experiment1(runs, first_seed, svg)
                              : group_mc::experiment2(runs, first_seed);
}
