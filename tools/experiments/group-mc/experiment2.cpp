// Paper 000 §4.2: does the group number survive a missed detection of the whole group?
#include <algorithm>
// LBP-PHD with the double label against the single label, P_d = 0.98.
#include <cstdint>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "scenario.hpp"
#include "skytrack/group/group_tracker.hpp"
#include "skytrack/metrics/ospa_gospa.hpp"

namespace group_mc {

namespace {

constexpr double kMatchDistance = 100.0;  // [m] an estimate this close is "on" a group

struct Continuity {
  int runs = 0;
  int runs_with_miss = 0;
  int runs_no_change = 0;           // no number change on any group over the run
  int runs_with_miss_kept = 0;      // with a miss, and every miss kept the number
  int misses = 0, misses_kept = 0;  // missed group detections followed by a re-detection
  double labels = 0.0;              // distinct group numbers per run
};

void run_one(const Scenario& sc, skytrack::group::GroupSpec spec, Continuity& c) {
  skytrack::group::GroupTracker tracker(spec);
  // Per truth group: the number on it in each scan (0 = none).
  std::map<int, std::vector<std::uint32_t>> on;
  std::map<std::uint32_t, bool> seen;
  skytrack::metrics::OspaGospa metric({kMatchDistance, 2.0});
  for (std::size_t k = 0; k < sc.scans.size(); ++k) {
    const auto& est = tracker.process(sc.scans[k].time, std::span(sc.scans[k].plots));
    std::vector<int> ids;
    const auto truth = sc.truth_positions(static_cast<int>(k) + 1, &ids);
    // One-to-one: the OSPA assignment with a 100 m cut-off (two groups crossing share one
    // estimate for a scan; only one of them is "on" it).
    std::vector<Eigen::VectorXd> positions;
    std::vector<std::uint32_t> numbers;
    for (const auto& e : est) {
      if (e.missed_scans == 0) {
        positions.push_back(e.position);
        numbers.push_back(e.label);
      }
    }
    std::vector<std::uint32_t> label(truth.size(), 0);
    for (const auto& pair : metric.compute(truth, positions).pairs) {
      label[static_cast<std::size_t>(pair.truth)] =
          numbers[static_cast<std::size_t>(pair.estimate)];
    }
    for (std::size_t t = 0; t < truth.size(); ++t) {
      on[ids[t]].push_back(label[t]);
      if (label[t] != 0) {
        seen[label[t]] = true;
      }
    }
  }
  bool changed = false, all_kept = true, any_miss = false;
  for (const auto& [id, labels] : on) {
    std::uint32_t last = 0;
    for (const std::uint32_t l : labels) {
      if (l != 0 && last != 0 && l != last) {
        changed = true;
      }
      last = l != 0 ? l : last;
    }
    // Each missed scan of this group: the number before it against the first one after.
    for (std::size_t k = 0; k < sc.scans.size(); ++k) {
      const auto& missed = sc.scans[k].missed;
      if (std::find(missed.begin(), missed.end(), id) == missed.end()) {
        continue;
      }
      std::uint32_t before = 0, after = 0;
      for (std::size_t b = k; b-- > 0 && before == 0;) {
        before = labels[b];
      }
      for (std::size_t a = k + 1; a < labels.size() && a <= k + 5 && after == 0; ++a) {
        after = labels[a];
      }
      if (before == 0 || after == 0) {
        continue;  // at the start, or not re-detected within 5 scans
      }
      any_miss = true;
      ++c.misses;
      if (before == after) {
        ++c.misses_kept;
      } else {
        all_kept = false;
      }
    }
  }
  ++c.runs;
  c.runs_with_miss += any_miss ? 1 : 0;
  c.runs_no_change += changed ? 0 : 1;
  c.runs_with_miss_kept += any_miss && all_kept ? 1 : 0;
  c.labels += static_cast<double>(seen.size());
}

}  // namespace

int experiment2(int runs, std::uint64_t first_seed) {
  Continuity result[2];
  for (int run = 0; run < runs; ++run) {
    const std::uint64_t seed = first_seed + static_cast<std::uint64_t>(run);
    const Scenario sc = make_experiment2(seed);
    for (int model = 0; model < 2; ++model) {
      skytrack::group::GroupSpec spec;
      spec.motion = skytrack::group::GroupMotion::kConstantVelocity;
      spec.detection_probability = 0.98;
      spec.births_per_box = 2;
      spec.seed = seed;
      spec.labels =
          model == 0 ? skytrack::group::LabelModel::kDouble : skytrack::group::LabelModel::kSingle;
      run_one(sc, spec, result[model]);
    }
  }
  fmt::print("## Experiment 2: {} runs, seeds {}..{}, P_d = 0.98\n\n", runs, first_seed,
             first_seed + static_cast<std::uint64_t>(runs) - 1);
  fmt::print(
      "| label | runs with a missed group | number kept through every miss (% of those "
      "runs) | misses with the number kept | runs without any number change | group "
      "numbers per run (truth: 2) |\n|---|---|---|---|---|---|\n");
  const char* names[2] = {"double (l1, l2)", "single (l1)"};
  for (int m = 0; m < 2; ++m) {
    const Continuity& c = result[m];
    fmt::print("| {} | {} | {} ({:.1f} %) | {} of {} | {} ({:.1f} %) | {:.2f} |\n", names[m],
               c.runs_with_miss, c.runs_with_miss_kept,
               100.0 * c.runs_with_miss_kept / std::max(c.runs_with_miss, 1), c.misses_kept,
               c.misses, c.runs_no_change, 100.0 * c.runs_no_change / std::max(c.runs, 1),
               c.labels / std::max(c.runs, 1));
  }
  return 0;
}

}  // namespace group_mc
