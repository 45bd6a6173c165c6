// `skytrack eval --identity` on a hand-made plot stream and track file
// (tests/tools/data/identity.*.jsonl): the figures it prints and writes as JSON.
//
// The case, 8 batches 4 s apart: aircraft A:1234 (plot 0 of each batch) and A:4321 (plot 1),
// and a generic 7000 plot (no identity) in batch 0.
//   A:1234: held by track 10 in every batch; batch 0's plot through an association of frame
//     1 that names its batch ("scan": 0).
//   A:4321: track 11 in batches 0-2, track 13 in 3-5, track 10 in 6 (the firm track likeliest
//     to hold it: 10 at 0.2 beats 13 at 0.1; tentative 12 at 0.9 does not count), no firm
//     track in 7 (tentative 12 only).
// By hand: 16 identity plots, 15 held (coverage 15/16); 2 segments, A:4321's held by 11 and
// 13 (3 plots each): 1 break; purity: track 10's dominant identity has 8 of its 9 plots,
// 11 and 13 all theirs: (8 + 3 + 3) / 15.
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <simdjson.h>
#include "cli_runner.hpp"

namespace {

using ::testing::HasSubstr;

using skytrack::testing::RunResult;

RunResult run(const std::string& arguments) {
  return skytrack::testing::run_skytrack(arguments);
}

std::string data(const std::string& name) {
  return skytrack::testing::tool_data(name);
}

const std::string kIdentity = "eval --identity --plots " + data("identity.plots.jsonl") +
                              " --tracks " + data("identity.tracks.jsonl");

/// The JSON object `eval --identity --json` prints (its line starts with {"segments").
std::string json_line(const std::string& output) {
  const std::size_t start = output.find("{\"segments\"");
  if (start == std::string::npos) return "";
  return output.substr(start, output.find('\n', start) - start);
}

double number(simdjson::dom::element element) {
  double value = std::nan("");
  if (element.get_double().get(value) == simdjson::SUCCESS) return value;
  std::int64_t integer = 0;
  if (element.get_int64().get(integer) == simdjson::SUCCESS) return static_cast<double>(integer);
  return std::nan("");
}

TEST(SkytrackEvalIdentity, JsonGivesTheHandCountedBreaksPurityAndCoverage) {
  // GIVEN the hand-made case; WHEN scored as JSON
  const RunResult r = run(kIdentity + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string line = json_line(r.output);
  ASSERT_FALSE(line.empty()) << r.output;
  simdjson::dom::parser parser;
  simdjson::dom::element doc;
  ASSERT_EQ(parser.parse(line).get(doc), simdjson::SUCCESS) << line;
  // THEN the figures are those counted by hand
  EXPECT_EQ(number(doc["identity_plots"]), 16.0);
  EXPECT_EQ(number(doc["held_plots"]), 15.0);
  EXPECT_EQ(number(doc["segments"]), 2.0);
  EXPECT_EQ(number(doc["breaks"]), 1.0);
  EXPECT_EQ(number(doc["segments_with_breaks"]), 1.0);
  EXPECT_NEAR(number(doc["breaks_per_segment"]), 0.5, 1e-12);
  EXPECT_NEAR(number(doc["purity"]), 14.0 / 15.0, 1e-12);
  EXPECT_NEAR(number(doc["coverage"]), 15.0 / 16.0, 1e-12);
  EXPECT_EQ(number(doc["code_changes"]), 0.0);
  EXPECT_EQ(number(doc["gap"]), 20.0);
  // ... and the worst segment is A:4321's, held by 11 and 13
  simdjson::dom::array worst;
  ASSERT_EQ(doc["worst"].get_array().get(worst), simdjson::SUCCESS);
  ASSERT_EQ(worst.size(), 2u);
  const simdjson::dom::element first = worst.at(0);
  std::string_view identity;
  ASSERT_EQ(first["identity"].get_string().get(identity), simdjson::SUCCESS);
  EXPECT_EQ(identity, "A:4321");
  EXPECT_EQ(number(first["plots"]), 8.0);
  EXPECT_EQ(number(first["held"]), 7.0);
  EXPECT_EQ(number(first["breaks"]), 1.0);
  EXPECT_EQ(number(first["first"]), 0.0);
  EXPECT_EQ(number(first["last"]), 28.0);
  std::vector<double> tracks;
  simdjson::dom::array track_array;
  ASSERT_EQ(first["tracks"].get_array().get(track_array), simdjson::SUCCESS);
  for (const simdjson::dom::element t : track_array) tracks.push_back(number(t));
  EXPECT_EQ(tracks, (std::vector<double>{11.0, 13.0}));
  // ... and the association naming no plot of the stream is reported
  EXPECT_THAT(r.output, HasSubstr("1 associations name no plot of"));
}

TEST(SkytrackEvalIdentity, TablePrintsTheSameFigures) {
  // GIVEN the hand-made case; WHEN scored as a table
  const RunResult r = run(kIdentity);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // THEN it prints the counts, purity and coverage to 4 decimals
  EXPECT_THAT(r.output, HasSubstr("16 identity plots in 2 segments (gap 20 s)"));
  EXPECT_THAT(r.output, HasSubstr("1 (0.5000 per segment), 1 segments with breaks"));
  EXPECT_THAT(r.output, HasSubstr("0.9333"));                        // purity 14/15
  EXPECT_THAT(r.output, HasSubstr("0.9375 (15 of 16 plots held)"));  // coverage
  EXPECT_THAT(r.output, HasSubstr("A:4321"));
  EXPECT_THAT(r.output, HasSubstr("11 13"));
}

TEST(SkytrackEvalIdentity, AShortGapSplitsEverySegment) {
  // GIVEN plots 4 s apart; WHEN a 2 s gap is given
  const RunResult r = run(kIdentity + " --gap 2 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  simdjson::dom::parser parser;
  simdjson::dom::element doc;
  ASSERT_EQ(parser.parse(json_line(r.output)).get(doc), simdjson::SUCCESS) << r.output;
  // THEN each plot is a segment of its own, and no segment can be broken; what is held is not
  // changed
  EXPECT_EQ(number(doc["segments"]), 16.0);
  EXPECT_EQ(number(doc["breaks"]), 0.0);
  EXPECT_EQ(number(doc["held_plots"]), 15.0);
  EXPECT_NEAR(number(doc["purity"]), 14.0 / 15.0, 1e-12);
}

TEST(SkytrackEvalIdentity, IdentityWithoutPlotsExitsTwo) {
  const RunResult r = run("eval --identity --tracks " + data("identity.tracks.jsonl"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--identity needs --plots"));
}

}  // namespace
