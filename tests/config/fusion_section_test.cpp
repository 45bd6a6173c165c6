// The fusion role's YAML: config/fusion.yaml, ranges, cross-key checks, unknown keys.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "skytrack/config/fusion_section.hpp"

namespace skytrack::config {
namespace {

using ::testing::HasSubstr;

std::string error_of(const std::string& text) {
  const auto spec = parse_fusion_config(text, "f.yaml");
  return spec ? std::string("(no error)") : spec.error().message;
}

TEST(FusionSection, ShippedFileLoadsWithTheDefaults) {
  const auto spec = load_fusion_config(std::string(SKYTRACK_SOURCE_DIR) + "/config/fusion.yaml");
  ASSERT_TRUE(spec) << spec.error().message;
  const fusion::FusionSpec d;
  EXPECT_EQ(spec->blend, d.blend);
  EXPECT_EQ(spec->metric, d.metric);
  EXPECT_EQ(spec->epsilon, d.epsilon);
  EXPECT_EQ(spec->cutoff, d.cutoff);
  EXPECT_EQ(spec->gate, d.gate);
  EXPECT_EQ(spec->label_penalty, d.label_penalty);
  EXPECT_EQ(spec->window, d.window);
  EXPECT_EQ(spec->accel_psd, d.accel_psd);
  EXPECT_EQ(spec->max_queued_frames, d.max_queued_frames);
}

TEST(FusionSection, ReadsEveryKey) {
  const auto spec = parse_fusion_config(
      "fusion: {output_sensor: 9, cycle: 2, window: 20, blend: fixed, epsilon: 0.5,\n"
      "  history_weight: 0.3, metric: euclidean, cutoff: 13, order: 1, label_penalty: 3,\n"
      "  gate: 5, sensor_timeout: 7, coast_time: 8, firm_only: false, accel_psd: 1,\n"
      "  missing_position_sigma: 50, missing_velocity_sigma: 5, max_queued_frames: 10}\n",
      "f.yaml");
  ASSERT_TRUE(spec) << spec.error().message;
  EXPECT_EQ(spec->output_sensor, 9u);
  EXPECT_EQ(spec->blend, fusion::Blend::kFixed);
  EXPECT_EQ(spec->metric, fusion::Metric::kEuclidean);
  EXPECT_EQ(spec->history_weight, 0.3);
  EXPECT_EQ(spec->order, 1.0);
  EXPECT_FALSE(spec->firm_only);
  EXPECT_EQ(spec->max_queued_frames, 10);
}

TEST(FusionSection, NamesFileLineKeyAndExpectation) {
  EXPECT_THAT(error_of("fusion:\n  cycle: 1\n  gate: -1\n"),
              HasSubstr("f.yaml:3: fusion.gate: expected"));
  EXPECT_THAT(error_of("fusion:\n  blend: sometimes\n"),
              HasSubstr("expected one of adaptive, fixed, got 'sometimes'"));
  EXPECT_THAT(error_of("fusion:\n  gate: 12\n"), HasSubstr("fusion.gate: expected gate < cutoff"));
  EXPECT_THAT(error_of("fusion:\n  cycle: 5\n  window: 2\n"),
              HasSubstr("expected cycle <= window"));
}

TEST(FusionSection, RefusesUnknownKeysAndAMissingSection) {
  EXPECT_THAT(error_of("fusion:\n  gaet: 3\n"), HasSubstr("f.yaml:2: fusion.gaet"));
  EXPECT_THAT(error_of("fusion: {}\nextra: 1\n"), HasSubstr("extra"));
  EXPECT_THAT(error_of("other: 1\n"), HasSubstr("fusion"));
}

TEST(FusionSection, ReadsASectionOfAnotherFile) {
  // As the daemon's configuration does with its own `fusion:` section.
  ErrorList errors("d.yaml");
  const YAML::Node node = YAML::Load("role: fusion\nfusion: {gate: 3}\n");
  fusion::FusionSpec spec;
  read_fusion_section(YamlSection(node["fusion"], "fusion", errors), spec);
  EXPECT_TRUE(errors.empty()) << errors.joined();
  EXPECT_EQ(spec.gate, 3.0);
}

}  // namespace
}  // namespace skytrack::config
