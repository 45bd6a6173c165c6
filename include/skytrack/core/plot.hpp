#pragma once
// Plot detections as they arrive from the radar (CONTRACTS.md §1). Frame: local ENU, metres,
// seconds, radians; azimuth clockwise from north, measured in the platform's body frame.
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace skytrack {

/// Measurement standard deviations; an absent value falls back to the next level
/// (plot -> scan -> profile).
struct MeasurementSigma {
  std::optional<double> range;       // [m]
  std::optional<double> azimuth;     // [rad]
  std::optional<double> elevation;   // [rad]
  std::optional<double> range_rate;  // [m/s]
  std::optional<double> x, y, z;     // [m]

  bool operator==(const MeasurementSigma&) const = default;
};

/// Fills each absent value of `primary` from `fallback`.
MeasurementSigma merged(const MeasurementSigma& primary, const MeasurementSigma& fallback);

enum class PlotForm : std::uint8_t { kPolar, kCartesian };

/// One detection. Polar plots use range/azimuth (+ optional elevation, range-rate) relative
/// to the platform; Cartesian plots use x/y (+ optional z) in the tracking frame.
struct Plot {
  std::int64_t id = 0;
  PlotForm form = PlotForm::kPolar;
  std::optional<double> time;        // [s] own measurement time; absent -> the scan's time
  double range = 0.0;                // [m]
  double azimuth = 0.0;              // [rad] clockwise from the body's nose
  std::optional<double> elevation;   // [rad] up from the body horizontal
  std::optional<double> range_rate;  // [m/s] positive when opening
  double x = 0.0, y = 0.0;           // [m]
  std::optional<double> z;           // [m]
  std::optional<double> snr_db;
  std::optional<double> amplitude;
  MeasurementSigma sigma;  // per-plot override
  // Secondary-radar (transponder) attributes, where the reply carried them.
  std::optional<std::uint16_t> mode3a;  // Mode 3/A code, 12 bits (4 octal digits)
  std::optional<std::uint32_t> mode_s;  // Mode S aircraft address, 24 bits
  std::optional<double> flight_level;   // Mode C / S pressure altitude [100 ft]

  bool operator==(const Plot&) const = default;
};

/// Sensor platform state for one scan. Attitude is [heading (clockwise from north), pitch
/// (nose up), roll (right wing down)] in radians.
struct PlatformState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // [m]
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // [m/s]
  Eigen::Vector3d attitude = Eigen::Vector3d::Zero();  // [rad]

  bool operator==(const PlatformState&) const = default;
};

/// The body-frame azimuth sector a batch's sweep covered, clockwise from `from` to `to`
/// [rad] (`to` < `from` when it crosses +-pi). A batch without one covers all directions.
struct AzimuthSector {
  double from = 0.0;
  double to = 0.0;

  /// True when `azimuth` lies in the sector.
  bool contains(double azimuth) const;
  bool operator==(const AzimuthSector&) const = default;
};

/// One batch of plots from one sensor: a revolution or a sector of it.
struct PlotScan {
  std::uint32_t sensor = 0;
  std::uint64_t scan = 0;
  double time = 0.0;  // [s] the batch's reference time
  PlatformState platform;
  MeasurementSigma sigma;                 // scan-level defaults
  std::optional<AzimuthSector> coverage;  // absent: the whole surroundings
  std::vector<Plot> plots;

  bool operator==(const PlotScan&) const = default;
};

/// The time a plot was measured at.
inline double plot_time(const Plot& plot, const PlotScan& scan) {
  return plot.time.value_or(scan.time);
}

}  // namespace skytrack
