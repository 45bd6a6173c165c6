// The core library is pure C++ over Eigen: no YAML, logging, DDS or JSON header may reach it,
// directly or through a project header it includes (DESIGN.md, "Core and adapters").
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

const fs::path kRoot = SKYTRACK_SOURCE_DIR;
// The families compiled into skytrack_core (src/CMakeLists.txt).
const char* const kCoreFamilies[] = {"core",      "geometry",    "motion",  "measurement",
                                     "filter",    "association", "clutter", "preprocess",
                                     "bernoulli", "extended",    "group",   "tracking",
                                     "pipeline",  "metrics",     "sim"};
const std::regex kInclude(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
const std::regex kForbidden(
    R"(^(yaml-cpp/|spdlog/|dds/|ddsc/|idl/|simdjson|skytrack/(config/profile_loader|config/scenario_loader|config/yaml|io/|dds/|daemon/|asterix/)))");

struct Finding {
  std::string file;
  std::string header;
};

/// Follows the project's own includes from `file`, collecting forbidden headers it reaches.
void scan(const fs::path& file, std::set<fs::path>& seen, std::vector<Finding>& out) {
  if (!seen.insert(file).second) return;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, kInclude)) continue;
    const std::string header = m[2];
    if (std::regex_search(header, kForbidden)) {
      out.push_back({fs::relative(file, kRoot).string(), header});
      continue;
    }
    if (header.starts_with("skytrack/")) {
      const fs::path next = kRoot / "include" / header;
      if (fs::exists(next)) scan(next, seen, out);
    } else if (m[1] == "\"") {
      const fs::path next = file.parent_path() / header;
      if (fs::exists(next)) scan(next, seen, out);
    }
  }
}

TEST(CorePurity, NoAdapterHeaderReachesTheCoreLibrary) {
  std::set<fs::path> seen;
  std::vector<Finding> findings;
  std::size_t files = 0;
  for (const char* family : kCoreFamilies) {
    for (const fs::path& dir : {kRoot / "src" / family, kRoot / "include" / "skytrack" / family}) {
      if (!fs::exists(dir)) continue;
      for (const auto& entry : fs::directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        ++files;
        scan(entry.path(), seen, findings);
      }
    }
  }
  EXPECT_GT(files, 50u);  // the walk found the core's files
  for (const Finding& f : findings) ADD_FAILURE() << f.file << " includes " << f.header;
}

}  // namespace
