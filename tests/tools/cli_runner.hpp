#pragma once
// Runs the built `skytrack` binary (SKYTRACK_TOOL) as a user would, for the tool tests.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>

namespace skytrack::testing {

struct RunResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

/// `skytrack ARGUMENTS`, its exit code and everything it printed.
inline RunResult run_skytrack(const std::string& arguments) {
  const std::string command = std::string(SKYTRACK_TOOL) + " " + arguments + " 2>&1";
  RunResult result;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe.get())) > 0) {
    result.output.append(buffer.data(), n);
  }
  const int status = pclose(pipe.release());
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

/// A file under tests/tools/data/.
inline std::string tool_data(const std::string& name) {
  return std::string(SKYTRACK_SOURCE_DIR) + "/tests/tools/data/" + name;
}

}  // namespace skytrack::testing
