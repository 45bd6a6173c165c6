#pragma once
// Plot-to-track association basics as a profile gives them (`association`), shared by the
// modes that associate.
// Plain structs in skytrack::config, the profile's namespace (profile.hpp gathers them);
// defaults and ranges in config/README.md.
#include <optional>
#include <string_view>

namespace skytrack::config {

enum class AssociationMethod { kJpda, kGnn };

/// Local clutter density (a clutter map) on top of the batch-wide `auto` estimate.
struct ClutterMapSpec {
  bool enabled = true;
  double range_cell = 5000.0;      // [m] polar plots
  double azimuth_cell = 0.05;      // [rad] polar plots
  double cartesian_cell = 5000.0;  // [m] x and y of Cartesian plots
  bool operator==(const ClutterMapSpec&) const = default;
};

struct AssociationSpec {
  AssociationMethod method = AssociationMethod::kJpda;
  double gate_probability = 0.999;     // P_G of the (non-manoeuvre) validation gate, in (0, 1)
  double detection_probability = 0.9;  // P_D, in (0, 1]
  // Clutter spatial density in the tracking frame [1/m^2 in 2-D, 1/m^3 in 3-D]; empty means
  // "auto": estimated from each scan.
  std::optional<double> clutter_density;
  ClutterMapSpec clutter_map;       // with auto only
  int max_exact_cluster_size = 32;  // [tracks] exact JPDA marginals up to this cluster size
  int k_best = 100;                 // joint events from Murty's k-best above it
  bool operator==(const AssociationSpec&) const = default;
};

constexpr std::string_view to_string(AssociationMethod method) {
  return method == AssociationMethod::kJpda ? "jpda" : "gnn";
}

}  // namespace skytrack::config
