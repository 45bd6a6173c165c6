// Profile loader bounds: finite but absurd values refused, the engineering extremes admitted.
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "skytrack/config/profile_loader.hpp"

#include "profile_loader_test_support.hpp"

namespace skytrack::config {
namespace {

using test::error_of;
using test::kHeader;
using ::testing::HasSubstr;

TEST(ProfileLoader, ClutterMapCellsHavePhysicalBounds) {
  // GIVEN cells no radar resolves (zero, or positive but tiny: they would overflow the map's
  // cell indices) or wider than any coverage; THEN the loader refuses each, naming it
  EXPECT_THAT(error_of("association:\n  clutter_map: {enabled: true, azimuth_cell: 0}\n"),
              HasSubstr("p.yaml:4: association.clutter_map.azimuth_cell: expected a number in"));
  EXPECT_THAT(error_of("association:\n  clutter_map: {azimuth_cell: 1e-20}\n"),
              HasSubstr("association.clutter_map.azimuth_cell: expected a number in"));
  EXPECT_THAT(error_of("association:\n  clutter_map: {range_cell: 1e-20}\n"),
              HasSubstr("association.clutter_map.range_cell: expected a number in"));
  EXPECT_THAT(error_of("association:\n  clutter_map: {cartesian_cell: 1e9}\n"),
              HasSubstr("association.clutter_map.cartesian_cell: expected a number in"));
}

TEST(ProfileLoader, InputLimitsAreReadAndPhysicallyBounded) {
  const auto profile = parse_profile(
      kHeader + std::string("input_limits: {max_range: 500e3, max_time_jump: 60}\n"), "p.yaml");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_EQ(profile->input_limits.max_range, 500e3);
  EXPECT_EQ(profile->input_limits.max_time_jump, 60.0);
  // A bound below any radar's range or a batch interval would refuse every plot or batch.
  EXPECT_THAT(error_of("input_limits: {max_range: 10}\n"),
              HasSubstr("p.yaml:3: input_limits.max_range: expected a number in"));
  EXPECT_THAT(error_of("input_limits: {max_time_jump: 0.01}\n"),
              HasSubstr("input_limits.max_time_jump: expected a number in"));
  EXPECT_THAT(error_of("input_limits: {max_time_jump: 1e300}\n"),
              HasSubstr("input_limits.max_time_jump: expected a number in"));
}

/// A finite but absurd value, the key the loader must name, and the value as it shows it.
struct Absurd {
  std::string body;
  std::string key;
  std::string shown;
};

/// Each profile is refused with "key: expected a number (or an integer) in [a, b], got v"
/// (or "(a, b]").
void expect_refused(const std::vector<Absurd>& cases) {
  for (const Absurd& c : cases) {
    const std::string message = error_of(c.body);
    EXPECT_THAT(message, ::testing::ContainsRegex(c.key +
                                                  ": expected an? (number|integer) in "
                                                  "[[(][^])]+[])], got " +
                                                  c.shown))
        << c.body;
  }
}

/// One model of the given type, with its IMM and branching keys fitting a one-model list.
std::string one_model(const std::string& keys) {
  return "motion_models:\n  - {name: m, " + keys +
         "}\nmode_transition: [[1]]\ninitial_mode_probabilities: [1]\n"
         "branching: {manoeuvre_models: [m]}\n";
}

TEST(ProfileLoader, MeasurementSigmasHavePhysicalBounds) {
  // GIVEN sigmas no sensor has (their squares are 0, a singular R, or overflow) and
  // unscented scalings that collapse or blow up the sigma points; THEN each is refused
  expect_refused({
      {"measurement: {default_sigma: {range: 1e-300}}\n", "measurement.default_sigma.range",
       "1e-300"},
      {"measurement: {default_sigma: {x: 1e300}}\n", "measurement.default_sigma.x", "1e\\+300"},
      {"measurement: {default_sigma: {height: 1e-9}}\n", "measurement.default_sigma.height",
       "1e-09"},
      {"measurement: {default_sigma: {azimuth: 1e-300}}\n", "measurement.default_sigma.azimuth",
       "1e-300"},
      {"measurement: {default_sigma: {elevation: 10}}\n", "measurement.default_sigma.elevation",
       "10"},
      {"measurement: {default_sigma: {range_rate: 1e300}}\n",
       "measurement.default_sigma.range_rate", "1e\\+300"},
      {"measurement: {unscented: {alpha: 1e-300}}\n", "measurement.unscented.alpha", "1e-300"},
      {"measurement: {unscented: {kappa: 1e300}}\n", "measurement.unscented.kappa", "1e\\+300"},
      {"measurement: {unscented: {beta: 1e300}}\n", "measurement.unscented.beta", "1e\\+300"},
  });
}

TEST(ProfileLoader, MotionModelNoisesAndTimeConstantsHavePhysicalBounds) {
  expect_refused({
      {one_model("type: constant_velocity, accel_sigma: 1e300"), "motion_models\\[0\\].accel_sigma",
       "1e\\+300"},
      {one_model("type: constant_acceleration, jerk_sigma: 1e300"),
       "motion_models\\[0\\].jerk_sigma", "1e\\+300"},
      {one_model("type: singer, accel_sigma: 5, time_constant: 1e-300"),
       "motion_models\\[0\\].time_constant", "1e-300"},
      {one_model("type: coordinated_turn_estimated, accel_sigma: 1, turn_rate_sigma: 1e300"),
       "motion_models\\[0\\].turn_rate_sigma", "1e\\+300"},
      {one_model("type: coordinated_turn_estimated, accel_sigma: 1, turn_rate_sigma: 0.01, "
                 "initial_turn_rate_sigma: 1e-300"),
       "motion_models\\[0\\].initial_turn_rate_sigma", "1e-300"},
      {one_model("type: constant_velocity, accel_sigma: 1, vertical_accel_sigma: 1e300"),
       "motion_models\\[0\\].vertical_accel_sigma", "1e\\+300"},
      {"branching: {manoeuvre_accel_sigma: 1e300}\n", "branching.manoeuvre_accel_sigma",
       "1e\\+300"},
      {"branching: {last_motion_accel_sigma: 1e300}\n", "branching.last_motion_accel_sigma",
       "1e\\+300"},
  });
}

TEST(ProfileLoader, SpeedsDistancesAndDensitiesHavePhysicalBounds) {
  expect_refused({
      {"initiation: {max_speed: 1e300}\n", "initiation.max_speed", "1e\\+300"},
      {"initiation: {max_speed: 1e-300}\n", "initiation.max_speed", "1e-300"},
      {"initiation: {min_speed: 1e300, max_speed: 1e301}\n", "initiation.min_speed", "1e\\+300"},
      {"track_life: {delete_position_sigma: 1e300}\n", "track_life.delete_position_sigma",
       "1e\\+300"},
      {"track_life: {delete_position_sigma: 1e-300}\n", "track_life.delete_position_sigma",
       "1e-300"},
      {"clutter_rejection: {kernel_bandwidth: 1e-300}\n", "clutter_rejection.kernel_bandwidth",
       "1e-300"},
      {"clutter_rejection: {mean_shift: {bandwidth: 1e300}}\n",
       "clutter_rejection.mean_shift.bandwidth", "1e\\+300"},
      {"clutter_rejection: {mean_shift: {tolerance: 1e-300}}\n",
       "clutter_rejection.mean_shift.tolerance", "1e-300"},
      {"clutter_rejection: {mean_shift: {merge_distance: 1e300}}\n",
       "clutter_rejection.mean_shift.merge_distance", "1e\\+300"},
  });
  // The density keeps its own message (it may also be auto), with the range in it.
  EXPECT_THAT(error_of("association: {clutter_density: 1e-300}\n"),
              HasSubstr("association.clutter_density: expected auto or a number in [1e-20, 1] "
                        "[1/m^2 in 2-D, 1/m^3 in 3-D], got '1e-300'"));
}

TEST(ProfileLoader, CountsThatSizeLoopsAndMemoryHaveBounds) {
  expect_refused({
      {"association: {k_best: 1000000000}\n", "association.k_best", "1000000000"},
      {"association: {max_exact_cluster_size: 1000000000}\n", "association.max_exact_cluster_size",
       "1000000000"},
      {"clutter_rejection: {n_f: 1000000000}\n", "clutter_rejection.n_f", "1000000000"},
      {"clutter_rejection: {mean_shift: {max_iterations: 1000000000}}\n",
       "clutter_rejection.mean_shift.max_iterations", "1000000000"},
      {"initiation: {m: 3, n: 1000000000}\n", "initiation.n", "1000000000"},
      {"initiation: {m: 1000000000, n: 1000000000}\n", "initiation.m", "1000000000"},
      {"track_life: {confirm_m: 3, confirm_n: 40}\n", "track_life.confirm_n", "40"},
      {"track_life: {delete_confirmed_misses: 2147483647}\n", "track_life.delete_confirmed_misses",
       "2147483647"},
      {"track_life: {delete_tentative_misses: 1000000000}\n", "track_life.delete_tentative_misses",
       "1000000000"},
      {"branching: {max_children: 1000000}\n", "branching.max_children", "1000000"},
      {"branching: {max_total_branches: 1000000000, max_branches_per_father: 12}\n",
       "branching.max_total_branches", "1000000000"},
      {"branching: {max_branches_per_father: 1000000000, max_total_branches: 2000000000}\n",
       "branching.max_branches_per_father", "1000000000"},
      {"branching: {coast_sons: 1000000000}\n", "branching.coast_sons", "1000000000"},
      {"branching: {coast_son_looks: 1000000000}\n", "branching.coast_son_looks", "1000000000"},
  });
}

TEST(ProfileLoader, BoundsAdmitTheEngineeringExtremes) {
  // GIVEN values at the ends of each physical range; THEN the profile loads
  const auto profile = parse_profile(kHeader + std::string(R"(measurement:
  unscented: {alpha: 1.0e-4, beta: 100, kappa: 100}
  default_sigma: {range: 0.001, azimuth: 1.0e-6, elevation: 3.14159, range_rate: 20000,
                  x: 100000, y: 0.001, z: 100000, height: 0.001}
motion_models:
  - {name: m, type: singer, accel_sigma: 1000, time_constant: 0.1, vertical_accel_sigma: 0}
mode_transition: [[1]]
initial_mode_probabilities: [1]
association: {clutter_density: 1.0e-20, clutter_map: {enabled: false}, k_best: 10000,
              max_exact_cluster_size: 1000}
clutter_rejection: {kernel_bandwidth: 1, n_f: 1000,
                    mean_shift: {bandwidth: 100000, max_iterations: 1000, tolerance: 0.001}}
initiation: {m: 100, n: 100, min_speed: 0, max_speed: 20000}
track_life: {confirm_m: 32, confirm_n: 32, delete_tentative_misses: 1000,
             delete_confirmed_misses: 1000, delete_position_sigma: 1000000}
branching: {manoeuvre_models: [m], max_children: 100, max_branches_per_father: 10000,
            max_total_branches: 100000, coast_sons: 100, coast_son_looks: 1000,
            manoeuvre_accel_sigma: 1000}
)"),
                                     "p.yaml");
  EXPECT_TRUE(profile) << profile.error().message;
}

}  // namespace
}  // namespace skytrack::config
