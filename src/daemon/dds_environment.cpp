#include "skytrack/daemon/dds_environment.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace skytrack::daemon {
namespace {

namespace fs = std::filesystem;

std::string executable_path() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : self.string();
}

}  // namespace

std::vector<std::string> loopback_config_candidates(const std::string& exe) {
  std::vector<std::string> out;
  if (!exe.empty()) {
    const fs::path dir = fs::path(exe).parent_path();
    out.push_back((dir / "../share/skytrack/dds/loopback.xml").lexically_normal().string());
    out.push_back((dir / "../../config/dds/loopback.xml").lexically_normal().string());
    out.push_back((dir / "../../../config/dds/loopback.xml").lexically_normal().string());
  }
#ifdef SKYTRACK_SOURCE_DIR
  out.push_back(std::string(SKYTRACK_SOURCE_DIR) + "/config/dds/loopback.xml");
#endif
  return out;
}

bool is_loopback_only_config(const std::string& path) {
  std::ifstream in(path);
  if (!in) return false;
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  // Comments must not count: strip them before looking.
  const std::string body = std::regex_replace(xml, std::regex("<!--[\\s\\S]*?-->"), "");
  const bool loopback =
      std::regex_search(body, std::regex("<NetworkInterface[^>]*name=\"lo\"")) ||
      std::regex_search(body, std::regex("<NetworkInterface[^>]*address=\"127\\.0\\.0\\.1\""));
  const bool no_multicast =
      std::regex_search(body, std::regex("<AllowMulticast>\\s*false\\s*</AllowMulticast>"));
  return loopback && no_multicast;
}

Expected<std::string> ensure_dds_configuration() {
  return ensure_dds_configuration(loopback_config_candidates(executable_path()));
}

Expected<std::string> ensure_dds_configuration(const std::vector<std::string>& candidates) {
  if (const char* uri = std::getenv("CYCLONEDDS_URI"); uri != nullptr && *uri != '\0') {
    return "CYCLONEDDS_URI=" + std::string(uri) + " (set by the user)";
  }
  for (const std::string& path : candidates) {
    if (!is_loopback_only_config(path)) continue;
    const std::string uri = "file://" + fs::absolute(path).lexically_normal().string();
    if (setenv("CYCLONEDDS_URI", uri.c_str(), 1) != 0) break;
    return "CYCLONEDDS_URI=" + uri + " (shipped loopback configuration)";
  }
  std::string searched;
  for (const std::string& path : candidates) searched += "\n  " + path;
  return make_error(
      "no safe Cyclone DDS configuration: CYCLONEDDS_URI is not set and the shipped loopback "
      "configuration (loopback interface, no multicast) was not found at:" +
      searched +
      "\nRefusing to start DDS with Cyclone's default, which multicasts off the machine. Set "
      "CYCLONEDDS_URI=file:///path/to/loopback.xml (or a network configuration) explicitly.");
}

}  // namespace skytrack::daemon
