#pragma once
// Paper 004 §4 (Fig. 1, 2) as a Monte Carlo experiment over skytrack's TrackFusion: two
// sensors whose track estimates are the truth plus Gaussian errors of variance diag(1, 1)
// and diag(0.8, 0.8) m^2 per scan, 1 s scans, two targets that merge (case 1) or split
// (case 2) after 20 s (config/scenarios/paper004_fusion_*.yaml).
#include <cstdint>
#include <string>
#include <vector>

#include "skytrack/core/truth.hpp"
#include "skytrack/fusion/fusion_spec.hpp"

namespace skytrack::fusion_mc {

/// The truth of a case, one frame per scan, from its scenario file.
std::vector<TruthFrame> load_truth(const std::string& scenario_path);

/// Per scan over the runs: runs with the right association (each target's two local tracks
/// fused together, no other), and the summed count of fed system tracks.
struct ScanTally {
  double time = 0.0;
  int correct = 0;
  long system_tracks = 0;
};

/// `runs` runs from `first_seed`, the same noise for every spec (a paired comparison).
std::vector<std::vector<ScanTally>> run_monte_carlo(const std::vector<TruthFrame>& truth,
                                                    const std::vector<fusion::FusionSpec>& specs,
                                                    int runs, std::uint64_t first_seed);

/// The fusion parameters of the reproduction (docs/fusion.md): metres, c, alpha and gamma as
/// the shipped normalised defaults times the pair's sigma sqrt(1 + 0.8) m; `label_sigmas`
/// replaces alpha's default (0: no label hysteresis, as with the paper's constant label term).
fusion::FusionSpec paper_spec(fusion::Blend blend, double label_sigmas);

/// The base-distance check of docs/fusion.md: normalised against metres on targets whose
/// track errors differ (20-300 m); prints a Markdown table.
void run_metric_check(int runs, std::uint64_t first_seed);

}  // namespace skytrack::fusion_mc
