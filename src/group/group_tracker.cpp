// Paper 000: §3.1 preprocessing (clutter/mean_shift_partition) feeding the §3.2 filter.
#include "skytrack/group/group_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace skytrack::group {
namespace {

void require(bool ok, const char* what) {
  if (!ok) {
    throw std::invalid_argument(std::string("GroupSpec: ") + what);
  }
}

bool positive(double x) {
  return std::isfinite(x) && x > 0.0;
}
bool probability(double x) {
  return std::isfinite(x) && x >= 0.0 && x <= 1.0;
}

}  // namespace

void check_group_spec(const GroupSpec& s) {
  require(std::isfinite(s.turn_rate), "turn_rate must be finite");
  require(s.boxes_per_group >= 1, "boxes_per_group must be >= 1");
  require(positive(s.position_width) && positive(s.velocity_width), "box widths must be > 0");
  require(std::isfinite(s.jitter) && s.jitter >= 0.0, "jitter must be >= 0");
  require(std::isfinite(s.measurement_box_padding) && s.measurement_box_padding >= 0.0,
          "measurement_box_padding must be >= 0");
  require(s.births_per_box >= 0 && s.births_per_estimate >= 0, "birth counts must be >= 0");
  require(std::isfinite(s.birth_mass_per_box) && s.birth_mass_per_box >= 0.0,
          "birth_mass_per_box must be >= 0");
  require(positive(s.birth_speed), "birth_speed must be > 0");
  require(probability(s.survival_probability) && probability(s.detection_probability),
          "survival and detection probabilities must be in [0, 1]");
  require(std::isfinite(s.clutter_rate) && s.clutter_rate >= 0.0, "clutter_rate must be >= 0");
  require(positive(s.surveillance_area), "surveillance_area must be > 0");
  require(positive(s.extraction_threshold), "extraction_threshold must be > 0");
  require(std::isfinite(s.readmit_distance) && s.readmit_distance >= 0.0,
          "readmit_distance must be >= 0");
  require(s.max_missed >= 0, "max_missed must be >= 0");
  require(probability(s.shape_smoothing), "shape_smoothing must be in [0, 1]");
  require(std::isfinite(s.measurement_sigma) && s.measurement_sigma >= 0.0,
          "measurement_sigma must be >= 0");
  require(positive(s.member_detection_probability) && s.member_detection_probability <= 1.0,
          "member_detection_probability must be in (0, 1]");
}

void make_cells(std::span<const Eigen::Vector3d> positions,
                std::span<const clutter::PlotPartition> partitions, double padding,
                std::vector<GroupCell>& out) noexcept {
  out.clear();
  for (const clutter::PlotPartition& part : partitions) {
    GroupCell c;
    c.box.lower = part.box.lower.head<2>() - Eigen::Vector2d::Constant(padding);
    c.box.upper = part.box.upper.head<2>() + Eigen::Vector2d::Constant(padding);
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
    for (const int i : part.plots) {
      if (i < 0 || static_cast<std::size_t>(i) >= positions.size()) {
        continue;
      }
      const Eigen::Vector2d p = positions[static_cast<std::size_t>(i)].head<2>();
      if (!p.allFinite()) {
        continue;
      }
      sum += p;
      second += p * p.transpose();
      ++c.plots;
    }
    if (c.plots > 0) {
      c.mean = sum / c.plots;
      c.scatter = second / c.plots - c.mean * c.mean.transpose();
    }
    out.push_back(c);
  }
}

void readmit_plots(std::span<const Eigen::Vector3d> positions,
                   const clutter::ClutterRejectionResult& rejection, double distance,
                   std::vector<clutter::PlotPartition>& partitions) noexcept {
  if (!(distance > 0.0) || partitions.empty()) {
    return;
  }
  const std::size_t n = std::min(positions.size(), rejection.keep.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d p = positions[i].head<2>();
    if (rejection.keep[i] != 0 || !p.allFinite()) {
      continue;
    }
    double best = distance;
    clutter::PlotPartition* nearest = nullptr;
    for (clutter::PlotPartition& part : partitions) {
      const Eigen::Vector2d lo = part.box.lower.head<2>();
      const Eigen::Vector2d hi = part.box.upper.head<2>();
      const double d = (p - p.cwiseMax(lo).cwiseMin(hi)).norm();  // distance to the box
      if (d <= best) {
        best = d;
        nearest = &part;
      }
    }
    if (nearest != nullptr) {
      nearest->plots.push_back(static_cast<int>(i));
      nearest->box.lower.head<2>() = nearest->box.lower.head<2>().cwiseMin(p);
      nearest->box.upper.head<2>() = nearest->box.upper.head<2>().cwiseMax(p);
    }
  }
}

GroupTracker::GroupTracker(const GroupSpec& spec)
    : spec_((check_group_spec(spec), spec)), partitioner_(spec.preprocessing), filter_(spec) {}

const std::vector<GroupEstimate>& GroupTracker::process(
    double time, std::span<const PlotMeasurement> plots) noexcept {
  positions_.clear();
  for (const PlotMeasurement& m : plots) {
    Eigen::Vector3d p = approximate_position(m);
    p.z() = 0.0;
    positions_.push_back(p);
  }
  return process(time, std::span<const Eigen::Vector3d>(positions_));
}

const std::vector<GroupEstimate>& GroupTracker::process(
    double time, std::span<const Eigen::Vector3d> positions) noexcept {
  const std::vector<clutter::PlotPartition>& parts = partitioner_.partition(positions, 2);
  partitions_.resize(parts.size());
  for (std::size_t c = 0; c < parts.size(); ++c) {
    partitions_[c].plots.assign(parts[c].plots.begin(), parts[c].plots.end());
    partitions_[c].box = parts[c].box;
  }
  readmit_plots(positions, partitioner_.rejection(), spec_.readmit_distance, partitions_);
  make_cells(positions, partitions_, spec_.measurement_box_padding, cells_);
  return filter_.step(time, cells_);
}

const std::vector<GroupEstimate>& GroupTracker::process_cells(
    double time, std::span<const GroupCell> cells) noexcept {
  partitions_.clear();
  cells_.assign(cells.begin(), cells.end());
  return filter_.step(time, cells_);
}

}  // namespace skytrack::group
