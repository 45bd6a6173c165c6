// Profile loader branching options: manoeuvre noise, last motion, coast sons, clutter area keys.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "skytrack/config/profile_loader.hpp"

#include "profile_loader_test_support.hpp"

namespace skytrack::config {
namespace {

using test::error_of;
using test::kHeader;

/// A profile whose only keys besides its identity are `branching: {keys}`.
Expected<TrackingProfile> with_branching(const std::string& keys) {
  return parse_profile(kHeader + ("branching: {" + keys + "}\n"), "p.yaml");
}

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
