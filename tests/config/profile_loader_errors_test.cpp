// Profile loader errors: unknown keys, wrong types and values, cross-field checks, bad files.
#include <algorithm>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "skytrack/config/profile_loader.hpp"

#include "profile_loader_test_support.hpp"

namespace skytrack::config {
namespace {

using test::error_of;
using test::kHeader;
using ::testing::HasSubstr;

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
