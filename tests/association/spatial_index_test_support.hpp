#pragma once
// Shared by the spatial index tests (PlotIndex, GridIndex): the answer every index must give.
#include <vector>

#include <Eigen/Core>

namespace skytrack::test {

/// The points within `radius` of `centre` in the first `dims` coordinates, ascending, with
/// the indexes' arithmetic (squared differences summed in axis order).
inline std::vector<int> brute_force_within(const std::vector<Eigen::Vector3d>& points, int dims,
                                           const Eigen::Vector3d& centre, double radius) {
  std::vector<int> out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    double d2 = 0.0;
    for (int d = 0; d < dims; ++d) d2 += (centre[d] - points[i][d]) * (centre[d] - points[i][d]);
    if (d2 <= radius * radius) out.push_back(static_cast<int>(i));
  }
  return out;
}

}  // namespace skytrack::test
