#pragma once
// Ground truth (CONTRACTS.md §2): one frame per time, objects in the ENU tracking frame.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace skytrack {

enum class ObjectKind : std::uint8_t { kPoint, kGroup, kExtended };

std::string_view to_string(ObjectKind kind);
std::optional<ObjectKind> parse_object_kind(std::string_view text);

struct TruthObject {
  std::int64_t id = 0;
  ObjectKind kind = ObjectKind::kPoint;
  int dims = 2;                                        // 2 or 3 position components
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // [m], z = 0 when dims == 2
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // [m/s]
  std::optional<Eigen::Matrix2d> extent;               // SPD shape matrix X [m^2] (group, extended)
  std::optional<int> members;                          // number of targets in a group

  bool operator==(const TruthObject&) const = default;
};

struct TruthFrame {
  double time = 0.0;
  std::vector<TruthObject> objects;

  bool operator==(const TruthFrame&) const = default;
};

}  // namespace skytrack
