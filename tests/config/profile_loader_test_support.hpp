#pragma once
// Profile text helpers for the profile loader tests: a two-line identity and a body's error.
#include <string>

#include "skytrack/config/profile_loader.hpp"

namespace skytrack::config::test {

// Two lines of identity, so a test's own keys start at line 3.
inline constexpr const char* kHeader = "profile: {name: t, version: 1}\nmode: point\n";

inline std::string error_of(const std::string& body) {
  const auto profile = parse_profile(kHeader + body, "p.yaml");
  return profile ? std::string("(no error)") : profile.error().message;
}

}  // namespace skytrack::config::test
