#pragma once
// What one filter produced in one run, per scan.
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace group_mc {

struct ScanEstimates {
  std::vector<Eigen::VectorXd> positions;  // reported (detected) group centroids [m]
  std::vector<std::uint32_t> labels;       // group numbers (0 for the k-means filters)
  double group_count = 0.0;                // N-hat of eq. 28
};

struct RunRecord {
  std::vector<ScanEstimates> scans;
  double seconds = 0.0;  // wall time of the filter over the run (preprocessing included)
};

}  // namespace group_mc
