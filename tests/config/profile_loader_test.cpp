#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "skytrack/config/profile_loader.hpp"

namespace skytrack::config {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::string kDefaultProfile =
    std::string(SKYTRACK_SOURCE_DIR) + "/config/profiles/default.yaml";

// Two lines of identity, so a test's own keys start at line 3.
constexpr const char* kHeader = "profile: {name: t, version: 1}\nmode: point\n";

std::string error_of(const std::string& body) {
  const auto profile = parse_profile(kHeader + body, "p.yaml");
  return profile ? std::string("(no error)") : profile.error().message;
}

/// A profile whose only keys besides its identity are `branching: {keys}`.
Expected<TrackingProfile> with_branching(const std::string& keys) {
  return parse_profile(kHeader + ("branching: {" + keys + "}\n"), "p.yaml");
}

TEST(ProfileLoader, ShippedDefaultProfileLoads) {
  const auto profile = load_profile(kDefaultProfile);
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_EQ(profile->identity.name, "default");
  EXPECT_EQ(profile->mode, TrackingMode::kPoint);
  ASSERT_EQ(profile->motion_models.size(), 3u);
  EXPECT_EQ(profile->motion_models[1].name, "ct_left");
  EXPECT_GT(profile->motion_models[1].turn_rate, 0.0);  // positive = left
  EXPECT_TRUE(profile->point.branching.enabled);
  EXPECT_FALSE(profile->association.clutter_density.has_value());  // auto
}

TEST(ProfileLoader, EveryShippedProfileLoads) {
  const std::filesystem::path dir = std::filesystem::path(SKYTRACK_SOURCE_DIR) / "config/profiles";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const auto profile = load_profile(entry.path().string());
    EXPECT_TRUE(profile) << profile.error().message;
  }
  EXPECT_GE(files, 7);
}

TEST(ProfileLoader, PointSectionsAtTheTopLevelLoadAsInProfilesOfTheEarlierShape) {
  // GIVEN the same point-tracker keys under point: and, as profiles had them before mode
  // sections, at the top level
  const std::string keys[] = {"initiation:\n  m: 2\n", "track_life:\n  confirm_m: 2\n",
                              "branching:\n  max_children: 2\n"};
  std::string nested = "point:\n", flat;
  for (const std::string& k : keys) {
    flat += k;
    std::istringstream lines(k);
    for (std::string line; std::getline(lines, line);) nested += "  " + line + "\n";
  }
  // WHEN both load THEN they give the same profile
  const auto a = parse_profile(kHeader + nested, "p.yaml");
  const auto b = parse_profile(kHeader + flat, "p.yaml");
  ASSERT_TRUE(a) << a.error().message;
  ASSERT_TRUE(b) << b.error().message;
  EXPECT_TRUE(*a == *b);
  EXPECT_EQ(a->point.initiation.m, 2);
  EXPECT_EQ(a->point.track_life.confirm_m, 2);
  EXPECT_EQ(a->point.branching.max_children, 2);
}

TEST(ProfileLoader, PointSectionsInBothPlacesOrForAnotherModeAreRefusedWithTheWayOut) {
  // WHEN a profile has point: and a top-level branching THEN the message says where it goes
  const auto both =
      parse_profile(kHeader + std::string("point:\n  track_life: {}\nbranching: {}\n"), "p.yaml");
  ASSERT_FALSE(both);
  EXPECT_THAT(both.error().message, HasSubstr("branching"));
  EXPECT_THAT(both.error().message, HasSubstr("belongs under point: (point.branching)"));
  // WHEN a group profile has a point section THEN it is named as another mode's
  const auto other =
      parse_profile("profile: {name: t, version: 1}\nmode: group\npoint: {}\n", "p.yaml");
  ASSERT_FALSE(other);
  EXPECT_THAT(other.error().message, HasSubstr("applies to mode: point only"));
  // AND an unknown key under point: names its path
  const auto unknown = parse_profile(kHeader + std::string("point:\n  branchin: {}\n"), "p.yaml");
  ASSERT_FALSE(unknown);
  EXPECT_THAT(unknown.error().message, HasSubstr("point.branchin"));
}

TEST(ProfileLoader, BernoulliModeTakesTheCommonModelsAndItsOwnSection) {
  // GIVEN a Bernoulli profile with two models and its particles per model
  const auto profile = parse_profile(R"(profile: {name: b, version: 1}
mode: bernoulli
motion_models:
  - {name: cv, type: constant_velocity, accel_sigma: 3.0}
  - {name: turn, type: coordinated_turn, turn_rate: -0.1, accel_sigma: 8.0}
mode_transition: [[0.9, 0.1], [0.2, 0.8]]
initial_mode_probabilities: [0.7, 0.3]
association: {detection_probability: 0.8}
bernoulli: {particles: [100, 400], birth: velocity_prior, birth_velocity: [10, -20]}
)",
                                     "b.yaml");
  ASSERT_TRUE(profile) << profile.error().message;
  // THEN the filter's models, transition, birth probabilities and P_D are the common ones
  const bernoulli::BernoulliSpec& b = profile->bernoulli;
  EXPECT_EQ(b.model_count, 2);
  EXPECT_DOUBLE_EQ(b.models[0].turn_rate, 0.0);
  EXPECT_DOUBLE_EQ(b.models[1].turn_rate, -0.1);
  EXPECT_DOUBLE_EQ(b.models[1].accel_sigma, 8.0);
  EXPECT_EQ(b.models[0].particles, 100);
  EXPECT_EQ(b.models[1].particles, 400);
  EXPECT_DOUBLE_EQ(b.transition[1][0], 0.2);
  EXPECT_DOUBLE_EQ(b.birth_model_probabilities[1], 0.3);
  EXPECT_DOUBLE_EQ(b.detection_probability, 0.8);
  EXPECT_EQ(b.birth_proposal, bernoulli::BirthProposal::kVelocityPrior);
  EXPECT_DOUBLE_EQ(b.birth_velocity[1], -20.0);
}

TEST(ProfileLoader, BernoulliModeRefusesWhatItsFilterCannotRun) {
  const auto load = [](const std::string& body) {
    return parse_profile("profile: {name: b, version: 1}\n" + body, "b.yaml");
  };
  // a model type the particle filter has no dynamics for
  const auto singer = load(R"(mode: bernoulli
motion_models: [{name: s, type: singer}]
mode_transition: [[1.0]]
initial_mode_probabilities: [1.0]
)");
  ASSERT_FALSE(singer);
  EXPECT_THAT(singer.error().message, HasSubstr("takes constant_velocity and coordinated_turn"));
  // one particle count per model
  const auto counts = load("mode: bernoulli\nbernoulli: {particles: [100, 200]}\n");
  ASSERT_FALSE(counts);
  EXPECT_THAT(counts.error().message, HasSubstr("bernoulli.particles"));
  // 3-D, and a bernoulli section in a point profile
  EXPECT_FALSE(load("mode: bernoulli\ndimension: 3\n"));
  const auto other = load("mode: point\nbernoulli: {}\n");
  ASSERT_FALSE(other);
  EXPECT_THAT(other.error().message, HasSubstr("applies to mode: bernoulli only"));
}

TEST(ProfileLoader, GroupModeReadsItsSectionAndTakesTheCommonPreprocessing) {
  const auto profile = parse_profile(R"(profile: {name: g, version: 1}
mode: group
clutter_rejection: {enabled: true, kernel_bandwidth: 30.0}
group: {motion: constant_velocity, labels: single, max_missed: 0, clutter_rate: 4.0}
)",
                                     "g.yaml");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_EQ(profile->group.motion, group::GroupMotion::kConstantVelocity);
  EXPECT_EQ(profile->group.labels, group::LabelModel::kSingle);
  EXPECT_EQ(profile->group.max_missed, 0);
  EXPECT_DOUBLE_EQ(profile->group.clutter_rate, 4.0);
  EXPECT_DOUBLE_EQ(profile->group.preprocessing.kernel_bandwidth, 30.0);
  // a group section in a point profile, and a point section in a group profile
  const auto in_point = parse_profile(std::string(kHeader) + "group: {}\n", "g.yaml");
  ASSERT_FALSE(in_point);
  EXPECT_THAT(in_point.error().message, HasSubstr("applies to mode: group only"));
  const auto unknown = parse_profile(
      "profile: {name: g, version: 1}\nmode: group\n"
      "group: {lables: single}\n",
      "g.yaml");
  ASSERT_FALSE(unknown);
  EXPECT_THAT(unknown.error().message, HasSubstr("group.lables"));
}

TEST(ProfileLoader, ExtendedModeReadsItsEstimatorAndNestedSections) {
  const auto profile = parse_profile(R"(profile: {name: e, version: 1}
mode: extended
extended:
  estimator: random_matrix
  motion: {time_constant: 20.0}
  random_matrix: {initial_dof: 6.0}
  delete_misses: 5
  coast_constant_velocity: false
  clutter_scan_test: false
  one_object_split_test: false
  existence: {enabled: false, clutter_density: 2.0e-7}
)",
                                     "e.yaml");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_EQ(profile->extended.kind, extended::EstimatorKind::kRandomMatrix);
  EXPECT_DOUBLE_EQ(profile->extended.motion.time_constant, 20.0);
  EXPECT_DOUBLE_EQ(profile->extended.random_matrix.initial_dof, 6.0);
  EXPECT_EQ(profile->extended.delete_misses, 5);
  EXPECT_FALSE(profile->extended.coast_constant_velocity);
  EXPECT_FALSE(profile->extended.clutter_scan_test);
  EXPECT_FALSE(profile->extended.one_object_split_test);
  EXPECT_FALSE(profile->extended.existence.enabled);
  EXPECT_DOUBLE_EQ(profile->extended.existence.clutter_density, 2.0e-7);
  const auto typo = parse_profile(
      "profile: {name: e, version: 1}\nmode: extended\nextended: {smf: {scatering: 1}}\n",
      "e.yaml");
  ASSERT_FALSE(typo);
  EXPECT_THAT(typo.error().message, HasSubstr("extended.smf.scatering"));
}

TEST(ProfileLoader, ShippedDefaultProfileEqualsTheCompiledDefaults) {
  // The file documents the defaults; it must not drift from the struct initialisers.
  auto profile = load_profile(kDefaultProfile);
  ASSERT_TRUE(profile) << profile.error().message;
  profile->identity = {};
  EXPECT_TRUE(*profile == TrackingProfile{});
}

TEST(ProfileLoader, IdentityAloneGivesTheDefaults) {
  const auto profile = parse_profile("profile:\n  name: mine\n  version: 2.1\n", "p.yaml");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_EQ(profile->identity.version, "2.1");
  TrackingProfile expected;
  expected.identity = profile->identity;
  EXPECT_TRUE(*profile == expected);
}

TEST(ProfileLoader, ReadsEveryModelTypeAndOption) {
  const auto profile = parse_profile(kHeader + std::string(R"(dimension: 2
measurement: {update: unscented, unscented: {alpha: 0.5}, default_sigma: {x: 10}}
motion_models:
  - {name: cv, type: constant_velocity, accel_sigma: 0.5}
  - {name: ca, type: constant_acceleration, jerk_sigma: 2}
  - {name: right, type: coordinated_turn, accel_sigma: 1, turn_rate: -0.1}
  - {name: cte, type: coordinated_turn_estimated, accel_sigma: 1, turn_rate_sigma: 0.01}
  - {name: singer, type: singer, accel_sigma: 20, time_constant: 10}
mode_transition: [[0.6, 0.1, 0.1, 0.1, 0.1], [0.1, 0.6, 0.1, 0.1, 0.1],
                  [0.1, 0.1, 0.6, 0.1, 0.1], [0.1, 0.1, 0.1, 0.6, 0.1],
                  [0.1, 0.1, 0.1, 0.1, 0.6]]
initial_mode_probabilities: [0.2, 0.2, 0.2, 0.2, 0.2]
association:
  method: gnn
  clutter_density: 1e-8
  clutter_map: {enabled: false, range_cell: 2000, azimuth_cell: 0.02, cartesian_cell: 3000}
initiation: {gated_seed_beta: 0.2}
branching: {enabled: false, manoeuvre_models: [right, singer]}
)"),
                                     "p.yaml");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_EQ(profile->dimension, 2);
  EXPECT_EQ(profile->measurement.update, MeasurementUpdate::kUnscented);
  EXPECT_EQ(profile->measurement.unscented.alpha, 0.5);
  EXPECT_EQ(profile->measurement.default_sigma.x, 10.0);
  const auto& m = profile->motion_models;
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(m[0].type, MotionModelType::kConstantVelocity);
  EXPECT_EQ(m[1].type, MotionModelType::kConstantAcceleration);
  EXPECT_EQ(m[1].jerk_sigma, 2.0);
  EXPECT_EQ(m[2].type, MotionModelType::kCoordinatedTurn);
  EXPECT_EQ(m[2].turn_rate, -0.1);
  EXPECT_EQ(m[3].type, MotionModelType::kCoordinatedTurnEstimated);
  EXPECT_EQ(m[3].turn_rate_sigma, 0.01);
  EXPECT_EQ(m[4].type, MotionModelType::kSinger);
  EXPECT_EQ(m[4].time_constant, 10.0);
  EXPECT_EQ(profile->association.method, AssociationMethod::kGnn);
  EXPECT_EQ(profile->association.clutter_density, 1e-8);
  EXPECT_FALSE(profile->association.clutter_map.enabled);
  EXPECT_EQ(profile->association.clutter_map.range_cell, 2000.0);
  EXPECT_EQ(profile->association.clutter_map.azimuth_cell, 0.02);
  EXPECT_EQ(profile->association.clutter_map.cartesian_cell, 3000.0);
  EXPECT_THAT(profile->point.branching.manoeuvre_models, ElementsAre("right", "singer"));
  EXPECT_EQ(profile->point.initiation.gated_seed_beta, 0.2);
}

TEST(ProfileLoader, AcceptsEveryModeName) {
  for (const char* mode : {"point", "group", "extended", "bernoulli"}) {
    const auto profile =
        parse_profile("profile: {name: t, version: 1}\nmode: " + std::string(mode), "p.yaml");
    ASSERT_TRUE(profile) << profile.error().message;
    EXPECT_EQ(to_string(profile->mode), mode);
  }
}

TEST(ProfileLoader, UnknownKeyNamesThePathAndLine) {
  EXPECT_EQ(error_of("association:\n  method: jpda\n  gate_prob: 0.9\n"),
            "p.yaml:5: association.gate_prob: unknown key (known keys here: method, "
            "gate_probability, detection_probability, clutter_density, clutter_map, "
            "max_exact_cluster_size, k_best)");
}

TEST(ProfileLoader, ClutterMapNeedsAutoDensity) {
  EXPECT_EQ(error_of("association:\n  clutter_density: 1e-9\n  clutter_map: {enabled: true}\n"),
            "p.yaml:5: association.clutter_map.enabled: the clutter map refines clutter_density: "
            "auto; it cannot be on with a fixed clutter_density");
}

TEST(ProfileLoader, FixedClutterDensityTurnsTheMapOffUnlessAsked) {
  // GIVEN a fixed density and no word on the map; THEN the profile loads with the map off
  const auto fixed =
      parse_profile(std::string(kHeader) + "association:\n  clutter_density: 1e-9\n", "p.yaml");
  ASSERT_TRUE(fixed) << fixed.error().message;
  EXPECT_EQ(fixed->association.clutter_density, 1e-9);
  EXPECT_FALSE(fixed->association.clutter_map.enabled);
  // ... and its cells may still be written (they are only unused)
  EXPECT_EQ(error_of("association:\n  clutter_density: 1e-9\n  clutter_map: {range_cell: 2000}\n"),
            "(no error)");
  // GIVEN auto (or nothing): THEN the map is on, as before
  const auto automatic =
      parse_profile(std::string(kHeader) + "association:\n  clutter_density: auto\n", "p.yaml");
  ASSERT_TRUE(automatic);
  EXPECT_TRUE(automatic->association.clutter_map.enabled);
}

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

TEST(ProfileLoader, KeyOfAnotherModelTypeIsUnknown) {
  EXPECT_THAT(error_of("motion_models:\n  - name: cv\n    type: constant_velocity\n"
                       "    accel_sigma: 1\n    turn_rate: 0.1\n"),
              HasSubstr("p.yaml:7: motion_models[0].turn_rate: unknown key"));
}

TEST(ProfileLoader, WrongTypeSaysWhatWasExpectedAndFound) {
  EXPECT_EQ(error_of("association:\n  detection_probability: high\n"),
            "p.yaml:4: association.detection_probability: expected a finite number in (0, 1], "
            "got 'high'");
  EXPECT_EQ(error_of("branching:\n  enabled: sometimes\n"),
            "p.yaml:4: branching.enabled: expected true or false, got 'sometimes'");
}

TEST(ProfileLoader, OutOfRangeValueSaysTheRangeAndTheValue) {
  EXPECT_EQ(error_of("association:\n  gate_probability: 1.5\n"),
            "p.yaml:4: association.gate_probability: expected a number in (0, 1), got 1.5");
  EXPECT_EQ(error_of("track_life:\n  confirm_n: 0\n"),
            "p.yaml:4: track_life.confirm_n: expected an integer in [1, 32], got 0");
  EXPECT_EQ(error_of("initiation:\n  gated_seed_beta: 1.5\n"),
            "p.yaml:4: initiation.gated_seed_beta: expected a number in [0, 1], got 1.5");
  EXPECT_EQ(error_of("dimension: 4\n"),
            "p.yaml:3: dimension: expected an integer in [2, 3], got 4");
  EXPECT_EQ(error_of("mode_transition_interval: -4\n"),
            "p.yaml:3: mode_transition_interval: expected a number >= 0, got -4");
  const auto automatic = parse_profile(kHeader + std::string("dimension: auto\n"), "p.yaml");
  ASSERT_TRUE(automatic) << automatic.error().message;
  EXPECT_EQ(automatic->dimension, 0);
}

TEST(ProfileLoader, UnknownChoiceListsTheAllowedNames) {
  EXPECT_EQ(error_of("association: {method: mht}\n"),
            "p.yaml:3: association.method: expected one of jpda, gnn, got 'mht'");
}

TEST(ProfileLoader, TransitionMatrixMustHaveOneRowAndColumnPerModel) {
  EXPECT_EQ(error_of("mode_transition:\n  - [0.9, 0.1]\n  - [0.1, 0.9]\n"),
            "p.yaml:4: mode_transition: expected a 3x3 matrix (a row and a column per motion "
            "model), got 2x2");
}

TEST(ProfileLoader, TransitionRowsMustSumToOne) {
  EXPECT_EQ(error_of("mode_transition:\n  - [0.9, 0.05, 0.05]\n  - [0.2, 0.7, 0.02]\n"
                     "  - [0.2, 0.02, 0.78]\n"),
            "p.yaml:5: mode_transition[1]: expected a row summing to 1 (within 1e-6), got 0.92");
  EXPECT_EQ(error_of("mode_transition:\n  - [1.1, -0.05, -0.05]\n  - [0.2, 0.78, 0.02]\n"
                     "  - [0.2, 0.02, 0.78]\n"),
            "p.yaml:4: mode_transition[0]: expected probabilities in [0, 1], got -0.05");
}

TEST(ProfileLoader, NewModelListNeedsItsOwnTransitionMatrix) {
  EXPECT_EQ(error_of("motion_models:\n  - {name: cv, type: constant_velocity, accel_sigma: 1}\n"
                     "branching: {manoeuvre_models: [cv]}\n"),
            "p.yaml:1: mode_transition: expected a 1x1 matrix (a row and a column per motion "
            "model), got 3x3 (the default; set mode_transition)\n"
            "p.yaml:1: initial_mode_probabilities: expected one probability per motion model "
            "(1), got 3 (the default; set initial_mode_probabilities)");
}

TEST(ProfileLoader, InitialProbabilitiesMustSumToOne) {
  EXPECT_EQ(error_of("initial_mode_probabilities: [0.5, 0.1, 0.1]\n"),
            "p.yaml:3: initial_mode_probabilities: expected probabilities summing to 1 (within "
            "1e-6), got 0.7");
}

TEST(ProfileLoader, DuplicateModelNameIsAnError) {
  EXPECT_EQ(error_of("motion_models:\n"
                     "  - {name: cv, type: constant_velocity, accel_sigma: 1}\n"
                     "  - {name: ct, type: coordinated_turn, accel_sigma: 1, turn_rate: 0.1}\n"
                     "  - {name: cv, type: coordinated_turn, accel_sigma: 1, turn_rate: -0.1}\n"
                     "branching: {manoeuvre_models: [cv, ct]}\n"),
            "p.yaml:6: motion_models[2].name: expected a unique model name, got 'cv' again "
            "(first at motion_models[0])");
}

TEST(ProfileLoader, BranchingModelMustExist) {
  EXPECT_EQ(error_of("branching:\n  manoeuvre_models: [cv, hard_left]\n"),
            "p.yaml:4: branching.manoeuvre_models[1]: expected the name of a motion model (cv, "
            "ct_left, ct_right), got 'hard_left'");
}

TEST(ProfileLoader, DisabledBranchingNeedNotNameModels) {
  // GIVEN a one-model baseline profile without branching, the default manoeuvre models
  // (cv, ct_left, ct_right) do not apply.
  EXPECT_EQ(error_of("motion_models:\n  - {name: cv, type: constant_velocity, accel_sigma: 1}\n"
                     "mode_transition: [[1]]\ninitial_mode_probabilities: [1]\n"
                     "association: {method: gnn}\nbranching: {enabled: false}\n"),
            "(no error)");
}

TEST(ProfileLoader, ManoeuvreGateMustBeTheWiderOne) {
  EXPECT_EQ(error_of("branching: {manoeuvre_gate_probability: 0.9}\n"),
            "p.yaml:3: branching.manoeuvre_gate_probability: expected >= "
            "association.gate_probability (0.999) as the manoeuvre gate is the wider one, got 0.9");
}

TEST(ProfileLoader, CrossFieldOrderChecks) {
  EXPECT_EQ(error_of("track_life: {confirm_m: 5, confirm_n: 4}\n"),
            "p.yaml:3: track_life.confirm_m: expected confirm_m <= confirm_n (4), got 5");
  EXPECT_EQ(error_of("initiation: {min_speed: 100, max_speed: 50}\n"),
            "p.yaml:3: initiation.min_speed: expected min_speed < max_speed (50), got 100");
  EXPECT_EQ(error_of("clutter_rejection: {beta: 3, n_f: 3}\n"),
            "p.yaml:3: clutter_rejection.beta: expected beta < n_f (3) so that tau stays below "
            "f_max, got 3");
}

TEST(ProfileLoader, TurnRateInDegreesIsCaught) {
  EXPECT_THAT(error_of("motion_models:\n"
                       "  - {name: ct, type: coordinated_turn, accel_sigma: 1, turn_rate: 3}\n"
                       "mode_transition: [[1]]\ninitial_mode_probabilities: [1]\n"
                       "branching: {manoeuvre_models: [ct]}\n"),
              HasSubstr("p.yaml:4: motion_models[0].turn_rate: expected |turn_rate| <= 1 rad/s, "
                        "got 3 (is it in deg/s?"));
}

TEST(ProfileLoader, ModelTypeParametersAreRequired) {
  EXPECT_THAT(error_of("motion_models:\n  - {name: ct, type: coordinated_turn, accel_sigma: 1}\n"
                       "mode_transition: [[1]]\ninitial_mode_probabilities: [1]\n"
                       "branching: {manoeuvre_models: [ct]}\n"),
              HasSubstr("p.yaml:4: motion_models[0].turn_rate: missing required key"));
}

TEST(ProfileLoader, ClutterDensityIsAutoOrPositive) {
  EXPECT_EQ(error_of("association: {clutter_density: auto}\n"), "(no error)");
  EXPECT_EQ(error_of("association: {clutter_density: -1}\n"),
            "p.yaml:3: association.clutter_density: expected auto or a number in [1e-20, 1] "
            "[1/m^2 in 2-D, 1/m^3 in 3-D], got '-1'");
}

TEST(ProfileLoader, ReportsEveryErrorOfAFileAtOnce) {
  const std::string message =
      error_of("colour: red\nassociation: {gate_probability: 2}\ntrack_life: {confirm_m: 0}\n");
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 2) << message;
}

TEST(ProfileLoader, IdentityIsRequired) {
  const auto profile = parse_profile("mode: point\n", "p.yaml");
  ASSERT_FALSE(profile);
  EXPECT_EQ(profile.error().message,
            "p.yaml: profile.name: missing required key\n"
            "p.yaml: profile.version: missing required key");
}

TEST(ProfileLoader, MissingFileIsReported) {
  const auto profile = load_profile("/nonexistent/tracking.yaml");
  ASSERT_FALSE(profile);
  EXPECT_EQ(profile.error().message, "/nonexistent/tracking.yaml: cannot open file");
}

TEST(ProfileLoader, YamlSyntaxErrorGivesTheLine) {
  const auto parsed = parse_profile("profile:\n  name: t\n  version: [1\nmode: point\n", "p.yaml");
  ASSERT_FALSE(parsed);
  // yaml-cpp marks where it gave up: the line after the unclosed '['.
  EXPECT_EQ(parsed.error().message, "p.yaml: line 4: end of sequence flow not found");

  const std::string path = ::testing::TempDir() + "profile_syntax.yaml";
  std::ofstream(path) << "profile: {name: t, version: 1}\nassociation:\n  method: jpda\n"
                         " bad indent: 1\n";
  const auto loaded = load_profile(path);
  ASSERT_FALSE(loaded);
  EXPECT_THAT(loaded.error().message, HasSubstr(path + ": line 4: "));
}

}  // namespace
}  // namespace skytrack::config

namespace skytrack::config {
namespace {

TEST(ProfileLoader, ManoeuvreAccelerationMustBePositive) {
  EXPECT_THAT(error_of("branching:\n  manoeuvre_accel_sigma: 0\n"),
              ::testing::HasSubstr("branching.manoeuvre_accel_sigma"));
  EXPECT_THAT(error_of("branching:\n  ambiguity_beta: 0\n"),
              ::testing::HasSubstr("branching.ambiguity_beta"));
  const auto profile = with_branching("manoeuvre_accel_sigma: 35.5");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_DOUBLE_EQ(profile->point.branching.manoeuvre_accel_sigma, 35.5);
}

TEST(ProfileLoader, CoastOnLastMotionIsASwitch) {
  const auto profile = with_branching("coast_on_last_motion: true");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_TRUE(profile->point.branching.coast_on_last_motion);
  EXPECT_TRUE(TrackingProfile{}.point.branching.coast_on_last_motion);
  // Off alone: the options that need it keep their (inert) defaults without an error.
  const auto off = with_branching("coast_on_last_motion: false");
  ASSERT_TRUE(off) << off.error().message;
  EXPECT_FALSE(off->point.branching.coast_on_last_motion);
  EXPECT_THAT(error_of("branching:\n  coast_on_last_motion: 2\n"),
              ::testing::HasSubstr("branching.coast_on_last_motion"));
}

TEST(ProfileLoader, LastMotionGateNeedsCoastOnLastMotion) {
  const auto profile =
      with_branching("coast_on_last_motion: true, non_manoeuvre_gate: last_motion");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_EQ(profile->point.branching.non_manoeuvre_gate, NonManoeuvreGate::kLastMotion);
  EXPECT_EQ(TrackingProfile{}.point.branching.non_manoeuvre_gate, NonManoeuvreGate::kLastMotion);
  EXPECT_THAT(
      error_of("branching:\n  coast_on_last_motion: false\n  non_manoeuvre_gate: "
               "last_motion\n"),
      ::testing::HasSubstr("non_manoeuvre_gate: needs branching.coast_on_last_motion: true"));
  EXPECT_THAT(error_of("branching:\n  non_manoeuvre_gate: cv\n"),
              ::testing::HasSubstr("branching.non_manoeuvre_gate"));
}

TEST(ProfileLoader, CoastSonsAndTheHeldMotionsNoiseNeedCoastOnLastMotion) {
  const auto profile = with_branching(
      "coast_on_last_motion: true, coast_sons: 3, coast_son_doubt: 0.2, last_motion_accel_sigma: "
      "0.5");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_EQ(profile->point.branching.coast_sons, 3);
  EXPECT_DOUBLE_EQ(profile->point.branching.coast_son_doubt, 0.2);
  EXPECT_DOUBLE_EQ(profile->point.branching.last_motion_accel_sigma, 0.5);
  EXPECT_EQ(TrackingProfile{}.point.branching.coast_sons, 5);
  EXPECT_DOUBLE_EQ(TrackingProfile{}.point.branching.last_motion_accel_sigma, 0.5);
  EXPECT_THAT(error_of("branching:\n  coast_on_last_motion: false\n  coast_sons: 1\n"),
              ::testing::HasSubstr("coast_sons: needs branching.coast_on_last_motion: true"));
  EXPECT_THAT(
      error_of("branching:\n  coast_on_last_motion: false\n  last_motion_accel_sigma: 0.5\n"),
      ::testing::HasSubstr("needs branching.coast_on_last_motion: true"));
  EXPECT_THAT(error_of("branching:\n  coast_sons: -1\n"),
              ::testing::HasSubstr("branching.coast_sons"));
  EXPECT_THAT(error_of("branching:\n  coast_son_doubt: 0\n"),
              ::testing::HasSubstr("branching.coast_son_doubt"));
}

TEST(ProfileLoader, DetectabilityChainReadsItsTwoProbabilities) {
  const auto profile = with_branching("detectability: {hide: 0.1, reveal: 0.5}");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_DOUBLE_EQ(profile->point.branching.detectability.hide, 0.1);
  EXPECT_DOUBLE_EQ(profile->point.branching.detectability.reveal, 0.5);
  EXPECT_EQ(TrackingProfile{}.point.branching.detectability,
            (config::DetectabilitySpec{.hide = 0.05, .reveal = 0.3}));
  EXPECT_THAT(error_of("branching:\n  detectability: {hide: 1.5}\n"),
              ::testing::HasSubstr("branching.detectability.hide"));
  EXPECT_THAT(error_of("branching:\n  detectability: {reveal: 0}\n"),
              ::testing::HasSubstr("branching.detectability.reveal"));
  EXPECT_THAT(error_of("branching:\n  detectability: {hidden: 0.1}\n"),
              ::testing::HasSubstr("branching.detectability.hidden"));
}

TEST(ProfileLoader, CoastSonWindowAndClutterAreaLastMotionNeedTheirOptions) {
  const auto profile = with_branching(
      "coast_on_last_motion: true, coast_sons: 3, coast_son_looks: 6, last_motion_false_plots: "
      "0.3");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_EQ(profile->point.branching.coast_son_looks, 6);
  EXPECT_DOUBLE_EQ(profile->point.branching.last_motion_false_plots, 0.3);
  EXPECT_EQ(TrackingProfile{}.point.branching.coast_son_looks, 8);
  EXPECT_DOUBLE_EQ(TrackingProfile{}.point.branching.last_motion_false_plots, 0.3);
  EXPECT_THAT(error_of("branching:\n  coast_sons: 0\n  coast_son_looks: 6\n"),
              ::testing::HasSubstr("coast_son_looks: needs branching.coast_sons > 0"));
  EXPECT_THAT(
      error_of("branching:\n  coast_on_last_motion: false\n"
               "  last_motion_false_plots: 0.3\n"),
      ::testing::HasSubstr("last_motion_false_plots: needs branching.coast_on_last_motion"));
  EXPECT_THAT(error_of("branching:\n  last_motion_false_plots: -1\n"),
              ::testing::HasSubstr("branching.last_motion_false_plots"));
}

TEST(ProfileLoader, ClutterAreaKeysReadFromTheirSubBlockOrTheirFlatNames) {
  // The sub-block and the flat keys of profiles written before it give the same spec.
  const auto block = with_branching(
      "clutter_area: {false_plots: 0.2, hold_last_motion: true, gate: union, "
      "held_accel_sigma: 0.7, coast_sons: 2, coast_son_doubt: 0.3, coast_son_looks: 4, "
      "detectability: {hide: 0.1, reveal: 0.4}}");
  const auto flat = with_branching(
      "last_motion_false_plots: 0.2, coast_on_last_motion: true, non_manoeuvre_gate: union, "
      "last_motion_accel_sigma: 0.7, coast_sons: 2, coast_son_doubt: 0.3, coast_son_looks: 4, "
      "detectability: {hide: 0.1, reveal: 0.4}");
  ASSERT_TRUE(block) << block.error().message;
  ASSERT_TRUE(flat) << flat.error().message;
  EXPECT_EQ(block->point.branching, flat->point.branching);
  EXPECT_DOUBLE_EQ(block->point.branching.last_motion_false_plots, 0.2);
  EXPECT_EQ(block->point.branching.non_manoeuvre_gate, NonManoeuvreGate::kUnion);
  EXPECT_DOUBLE_EQ(block->point.branching.detectability.reveal, 0.4);
  // Both forms of one key, a dependency and an unknown key, each named with its path.
  EXPECT_THAT(error_of("branching:\n  coast_sons: 2\n  clutter_area: {coast_sons: 3}\n"),
              ::testing::HasSubstr("branching.clutter_area.coast_sons: given twice: also as "
                                   "branching.coast_sons"));
  EXPECT_THAT(error_of("branching:\n  clutter_area: {hold_last_motion: false, gate: "
                       "last_motion}\n"),
              ::testing::HasSubstr("branching.clutter_area.gate: needs "
                                   "branching.clutter_area.hold_last_motion: true"));
  EXPECT_THAT(error_of("branching:\n  clutter_area: {coast_son: 1}\n"),
              ::testing::HasSubstr("branching.clutter_area.coast_son"));
}

TEST(ProfileLoader, BranchConfirmationIsMOfNOrExistence) {
  const auto profile = with_branching("confirmation: m_of_n");
  ASSERT_TRUE(profile) << profile.error().message;
  EXPECT_EQ(profile->point.branching.confirmation, ConfirmationMethod::kMOfN);
  EXPECT_EQ(TrackingProfile{}.point.branching.confirmation, ConfirmationMethod::kExistence);
  EXPECT_THAT(error_of("branching:\n  confirmation: score\n"),
              ::testing::HasSubstr("branching.confirmation"));
}

}  // namespace
}  // namespace skytrack::config
