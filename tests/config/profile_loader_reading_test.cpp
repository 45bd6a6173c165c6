// Profile loader reading: the shipped profiles, the defaults, each mode's sections, every model.
#include <filesystem>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "skytrack/config/profile_loader.hpp"

#include "profile_loader_test_support.hpp"

namespace skytrack::config {
namespace {

using test::kHeader;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::string kDefaultProfile =
    std::string(SKYTRACK_SOURCE_DIR) + "/config/profiles/default.yaml";

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

}  // namespace
}  // namespace skytrack::config
