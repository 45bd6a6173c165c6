#include "skytrack/daemon/dds_environment.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace skytrack::daemon {
namespace {

using ::testing::HasSubstr;

const std::string kSource = SKYTRACK_SOURCE_DIR;

/// Restores CYCLONEDDS_URI when the test ends.
class UriGuard {
 public:
  UriGuard() {
    if (const char* v = std::getenv("CYCLONEDDS_URI")) saved_ = v;
  }
  ~UriGuard() {
    if (saved_) {
      setenv("CYCLONEDDS_URI", saved_->c_str(), 1);
    } else {
      unsetenv("CYCLONEDDS_URI");
    }
  }

 private:
  std::optional<std::string> saved_;
};

std::string temp_file(const std::string& name, const std::string& text) {
  const auto path =
      std::filesystem::temp_directory_path() / (name + "_" + std::to_string(getpid()) + ".xml");
  std::ofstream(path) << text;
  return path.string();
}

TEST(DdsEnvironment, ShippedLoopbackIsSafeAndTheNetworkExampleIsNot) {
  EXPECT_TRUE(is_loopback_only_config(kSource + "/config/dds/loopback.xml"));
  EXPECT_FALSE(is_loopback_only_config(kSource + "/config/dds/network.xml"));
  EXPECT_FALSE(is_loopback_only_config("/nonexistent.xml"));
}

TEST(DdsEnvironment, CommentedOutSettingsDoNotCount) {
  const std::string path = temp_file("commented",
                                     "<CycloneDDS><!-- <NetworkInterface name=\"lo\"/> "
                                     "<AllowMulticast>false</AllowMulticast> --></CycloneDDS>");
  EXPECT_FALSE(is_loopback_only_config(path));
  std::filesystem::remove(path);
}

TEST(DdsEnvironment, CandidatesCoverInstallPrefixAndBuildTree) {
  const auto c = loopback_config_candidates("/opt/skytrack/bin/skytrackd");
  ASSERT_GE(c.size(), 2u);
  EXPECT_EQ(c[0], "/opt/skytrack/share/skytrack/dds/loopback.xml");
  EXPECT_THAT(c, ::testing::Contains("/opt/config/dds/loopback.xml"));
}

TEST(DdsEnvironment, UsersChoiceIsKept) {
  UriGuard guard;
  setenv("CYCLONEDDS_URI", "file:///etc/my-dds.xml", 1);
  const auto r = ensure_dds_configuration({});
  ASSERT_TRUE(r);
  EXPECT_THAT(*r, HasSubstr("set by the user"));
  EXPECT_STREQ(std::getenv("CYCLONEDDS_URI"), "file:///etc/my-dds.xml");
}

TEST(DdsEnvironment, SetsTheFirstSafeCandidate) {
  UriGuard guard;
  unsetenv("CYCLONEDDS_URI");
  const std::string unsafe = kSource + "/config/dds/network.xml";
  const std::string safe = kSource + "/config/dds/loopback.xml";
  const auto r = ensure_dds_configuration({"/nonexistent.xml", unsafe, safe});
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(std::string(std::getenv("CYCLONEDDS_URI")), "file://" + safe);
}

TEST(DdsEnvironment, RefusesWhenNoSafeConfigurationExists) {
  // GIVEN no CYCLONEDDS_URI and only unsafe or missing candidates
  UriGuard guard;
  unsetenv("CYCLONEDDS_URI");
  const auto r =
      ensure_dds_configuration({"/nonexistent.xml", kSource + "/config/dds/network.xml"});
  // THEN it refuses, names where it looked, and leaves Cyclone unconfigured (not started)
  ASSERT_FALSE(r);
  EXPECT_THAT(r.error().message, HasSubstr("Refusing to start DDS"));
  EXPECT_THAT(r.error().message, HasSubstr("/nonexistent.xml"));
  EXPECT_EQ(std::getenv("CYCLONEDDS_URI"), nullptr);
}

}  // namespace
}  // namespace skytrack::daemon
