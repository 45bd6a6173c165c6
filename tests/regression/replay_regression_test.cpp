// Replay regression: shipped scenarios tracked with shipped profiles, every frame (tracks,
// associations, events) compared with committed expected digests to 1e-9. It pins the point
// tracker's behaviour across refactors; a change that means to alter the tracks regenerates
// the digests on purpose (tools/regenerate-regression.sh) and says why in its commit.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "skytrack/config/profile_loader.hpp"
#include "skytrack/config/scenario_loader.hpp"
#include "skytrack/pipeline/pipeline.hpp"
#include "skytrack/sim/simulator.hpp"

namespace skytrack {
namespace {

constexpr double kTolerance = 1e-9;  // relative, and absolute below 1
constexpr std::uint64_t kSeed = 1;

struct Case {
  const char* scenario;  // config/scenarios/<name>.yaml
  const char* profile;   // config/profiles/<name>.yaml
};

// Snapshot and rotating feeds, 2-D and 3-D, JPDA and GNN, branching on and off, clutter
// areas, manoeuvres, slow surface targets; and each other implemented mode.
const Case kCases[] = {
    {"default", "default"},
    {"default_snapshot", "default"},
    {"point_20_targets", "gnn"},
    {"paper003_exp2_missed_in_clutter", "default"},
    {"paper003_exp3_uturn", "no_branching"},
    {"airborne_30_targets", "airborne"},
    {"airport_surface", "ground_surveillance"},
    {"paper003_exp1_racetrack_figure_eight", "dense_clutter"},
    {"paper001_mmbpf", "bernoulli"},    // mode: bernoulli
    {"paper000_exp1_groups", "group"},  // mode: group
    {"paper002_extended", "extended"},  // mode: extended
    {"extended_crossing", "extended"},  // extended: four objects, a crossing, clutter
};

std::string source(const std::string& relative) {
  return std::string(SKYTRACK_SOURCE_DIR) + "/" + relative;
}

std::string expected_path(const Case& c) {
  return source(std::string("tests/regression/expected/") + c.scenario + "." + c.profile + ".txt");
}

/// One line per frame, track, association and event: the fields the output carries (of the
/// covariance, its diagonal).
void digest(const TrackFrame& f, std::ostream& out) {
  out << "F " << f.sensor << ' ' << f.scan << ' ' << f.time << ' ' << f.tracks.size() << ' '
      << f.associations.size() << ' ' << f.events.size() << '\n';
  for (const TrackReport& t : f.tracks) {
    out << "T " << t.id << ' ' << to_string(t.status) << ' ' << t.dims;
    for (int i = 0; i < 3; ++i) out << ' ' << t.position[i] << ' ' << t.velocity[i];
    // The variances; the covariances follow from the same filter arithmetic.
    const std::size_t n = 2 * static_cast<std::size_t>(t.dims);
    if (t.covariance.size() == n * n) {
      for (std::size_t i = 0; i < n; ++i) out << ' ' << t.covariance[i * n + i];
    }
    for (const auto& [mode, p] : t.modes) out << ' ' << mode << ' ' << p;
    if (t.quality) out << " q " << *t.quality;
    out << '\n';
  }
  for (const Association& a : f.associations) {
    out << "A " << a.track << ' ' << a.plot << ' ' << a.probability;
    if (a.scan) out << " s " << *a.scan;
    out << '\n';
  }
  for (const TrackEvent& e : f.events) out << "E " << type_name(e) << ' ' << e.track << '\n';
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// Why two digest lines differ beyond the tolerance, or empty.
std::string difference(const std::string& expected, const std::string& actual) {
  std::istringstream a(expected), b(actual);
  std::string x, y;
  for (int field = 0;; ++field) {
    const bool more_a = static_cast<bool>(a >> x), more_b = static_cast<bool>(b >> y);
    if (!more_a && !more_b) return {};
    if (more_a != more_b) return "a different number of fields";
    if (x == y) continue;
    char* end_x = nullptr;
    char* end_y = nullptr;
    const double u = std::strtod(x.c_str(), &end_x), v = std::strtod(y.c_str(), &end_y);
    const bool numbers = *end_x == '\0' && *end_y == '\0' && end_x != x.c_str();
    if (!numbers || std::abs(u - v) > kTolerance * std::max({1.0, std::abs(u), std::abs(v)})) {
      return "field " + std::to_string(field) + ": expected " + x + ", got " + y;
    }
  }
}

std::string run(const Case& c) {
  const auto scenario = config::load_scenario(source("config/scenarios/") + c.scenario + ".yaml");
  const auto profile = config::load_profile(source("config/profiles/") + c.profile + ".yaml");
  EXPECT_TRUE(scenario && profile);
  if (!scenario || !profile) return {};
  auto simulator = sim::Simulator::create(*scenario, kSeed);
  auto pipeline = Pipeline::create(*profile);
  EXPECT_TRUE(simulator && pipeline);
  if (!simulator || !pipeline) return {};
  std::ostringstream out;
  out.precision(12);  // 1e-9 relative needs no more
  while (auto batch = simulator->next()) {
    const ScanResult& result = pipeline->process(batch->plots);
    EXPECT_TRUE(result.accepted) << result.rejection;
    digest(result.frame, out);
  }
  return out.str();
}

/// The first difference between the committed digest and this run's beyond the tolerance
/// (frame and line: where the behaviour changed), or empty.
std::string first_difference(const Case& c, const std::string& expected,
                             const std::string& actual) {
  const auto want = lines_of(expected), got = lines_of(actual);
  std::string frame;
  for (std::size_t i = 0; i < std::min(want.size(), got.size()); ++i) {
    if (want[i].starts_with("F ")) frame = want[i];
    if (const std::string why = difference(want[i], got[i]); !why.empty()) {
      return std::string(c.scenario) + " x " + c.profile + ", line " + std::to_string(i + 1) +
             " (frame '" + frame + "'): " + why + "\n  expected: " + want[i] +
             "\n  got:      " + got[i];
    }
  }
  if (got.size() != want.size()) {
    return std::string(c.scenario) + " x " + c.profile + ": " + std::to_string(got.size()) +
           " lines, expected " + std::to_string(want.size());
  }
  return {};
}

class ReplayRegression : public ::testing::TestWithParam<Case> {};

TEST_P(ReplayRegression, TracksEqualTheCommittedDigest) {
  const Case& c = GetParam();
  const std::string actual = run(c);
  const std::string path = expected_path(c);
  std::ifstream file(path);
  const std::string expected =
      file ? std::string{std::istreambuf_iterator<char>(file), {}} : std::string();
  const std::string why = file ? first_difference(c, expected, actual) : "missing";
  // Regeneration rewrites only the digests that differ beyond the tolerance, so a change
  // touches no run it leaves alone (the last digits of a float may move between builds).
  if (std::getenv("SKYTRACK_REGENERATE_REGRESSION") != nullptr) {
    if (!why.empty()) std::ofstream(path) << actual;
    GTEST_SKIP() << (why.empty() ? "unchanged " : "regenerated ") << path;
  }
  ASSERT_TRUE(file) << path << " missing: tools/regenerate-regression.sh writes it";
  EXPECT_TRUE(why.empty()) << why;
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  return std::string(info.param.scenario) + "_x_" + info.param.profile;
}

INSTANTIATE_TEST_SUITE_P(ShippedScenarios, ReplayRegression, ::testing::ValuesIn(kCases),
                         case_name);

}  // namespace
}  // namespace skytrack
