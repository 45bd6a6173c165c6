#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "skytrack/config/yaml_section.hpp"

namespace skytrack::config {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

TEST(YamlSectionRange, DescribesItsBounds) {
  EXPECT_EQ(Range::positive().describe(), "> 0");
  EXPECT_EQ(Range::non_negative().describe(), ">= 0");
  EXPECT_EQ(Range::probability().describe(), "in [0, 1]");
  EXPECT_EQ(Range::open_probability().describe(), "in (0, 1]");
  EXPECT_EQ((Range{0.0, 1.0, true, true}).describe(), "in (0, 1)");
  EXPECT_EQ((Range{-std::numeric_limits<double>::infinity(), 5.0}).describe(), "<= 5");
  EXPECT_TRUE(Range::open_probability().contains(1.0));
  EXPECT_FALSE(Range::open_probability().contains(0.0));
}

TEST(YamlSection, ReadsValuesAndLeavesAbsentKeysAlone) {
  ErrorList errors("t.yaml");
  YamlSection s(YAML::Load("a: 2.5\nn: 3\nflag: true\nname: hello\n"), "", errors);
  double a = 0.0, absent = 7.0;
  int n = 0;
  bool flag = false;
  std::string name;
  s.number("a", a);
  s.number("absent", absent);
  s.integer("n", n);
  s.boolean("flag", flag);
  s.text("name", name);
  s.finish();
  EXPECT_THAT(errors.messages(), IsEmpty());
  EXPECT_EQ(a, 2.5);
  EXPECT_EQ(absent, 7.0);
  EXPECT_EQ(n, 3);
  EXPECT_TRUE(flag);
  EXPECT_EQ(name, "hello");
}

TEST(YamlSection, OutOfRangeNumberNamesFileLinePathRangeAndValue) {
  ErrorList errors("t.yaml");
  YamlSection root(YAML::Load("gate:\n  p: 1.5\n"), "", errors);
  YamlSection gate = root.section("gate");
  double p = 0.5;
  gate.number("p", p, Range{0.0, 1.0, true, true});
  EXPECT_EQ(p, 0.5);  // unchanged on error
  EXPECT_THAT(errors.messages(),
              ElementsAre("t.yaml:2: gate.p: expected a number in (0, 1), got 1.5"));
}

TEST(YamlSection, WrongTypeSaysWhatWasFound) {
  ErrorList errors("t.yaml");
  YamlSection s(YAML::Load("a: abc\nb: [1, 2]\nc: maybe\nd: {x: 1}\n"), "", errors);
  double a = 0.0, b = 0.0;
  bool c = false;
  std::string d;
  s.number("a", a, Range::positive());
  s.number("b", b);
  s.boolean("c", c);
  s.text("d", d);
  EXPECT_THAT(errors.messages(), ElementsAre("t.yaml:1: a: expected a finite number > 0, got 'abc'",
                                             "t.yaml:2: b: expected a finite number, got a list",
                                             "t.yaml:3: c: expected true or false, got 'maybe'",
                                             "t.yaml:4: d: expected a string, got a mapping"));
}

TEST(YamlSection, IntegerRejectsFractionsButAcceptsWholeDecimals) {
  ErrorList errors("t.yaml");
  YamlSection s(YAML::Load("a: 2.5\nb: 3.0\nc: 0\nd: 3000000000\n"), "", errors);
  int a = 1, b = 1, c = 1, d = 1;
  s.integer("a", a, Range{1.0});
  s.integer("b", b, Range{1.0});
  s.integer("c", c, Range{1.0});
  s.integer("d", d);
  EXPECT_EQ(a, 1);
  EXPECT_EQ(b, 3);
  EXPECT_EQ(c, 1);
  EXPECT_EQ(d, 1);
  // The int limits do not leak into the range shown ("in [1, 2.14748e+09]").
  EXPECT_THAT(errors.messages(),
              ElementsAre("t.yaml:1: a: expected an integer >= 1, got '2.5'",
                          "t.yaml:3: c: expected an integer >= 1, got 0",
                          "t.yaml:4: d: expected a 32-bit integer, got 3000000000"));
}

TEST(YamlSection, ChoiceAcceptsOnlyListedNames) {
  ErrorList errors("t.yaml");
  YamlSection s(YAML::Load("good: gnn\nbad: murty\n"), "assoc", errors);
  std::string good = "jpda", bad = "jpda", absent = "jpda";
  s.choice("good", good, {"jpda", "gnn"});
  s.choice("bad", bad, {"jpda", "gnn"});
  s.choice("absent", absent, {"jpda", "gnn"});
  EXPECT_EQ(good, "gnn");
  EXPECT_EQ(bad, "jpda");
  EXPECT_EQ(absent, "jpda");
  EXPECT_THAT(errors.messages(),
              ElementsAre("t.yaml:2: assoc.bad: expected one of jpda, gnn, got 'murty'"));
}

TEST(YamlSection, FinishListsUnknownKeysWithLineAndKnownKeys) {
  ErrorList errors("t.yaml");
  YamlSection s(YAML::Load("a: 1\ncolour: red\nb: 2\nsize: 3\n"), "top", errors);
  double a = 0.0, b = 0.0;
  s.number("a", a);
  s.number("b", b);
  s.finish();
  EXPECT_THAT(errors.messages(),
              ElementsAre("t.yaml:2: top.colour: unknown key (known keys here: a, b)",
                          "t.yaml:4: top.size: unknown key (known keys here: a, b)"));
}

TEST(YamlSection, FinishReportsDuplicateKeys) {
  // yaml-cpp keeps both and readers would silently see only the first.
  ErrorList errors("t.yaml");
  YamlSection s(YAML::Load("a: 1\na: 2\n"), "", errors);
  double a = 0.0;
  s.number("a", a);
  s.finish();
  EXPECT_EQ(a, 1.0);
  EXPECT_THAT(errors.messages(),
              ElementsAre("t.yaml:2: a: duplicate key (only the first is used)"));
}

TEST(YamlSection, MissingRequiredKeyPointsAtItsMapping) {
  ErrorList errors("t.yaml");
  YamlSection root(YAML::Load("x: 1\nmodel:\n  type: cv\n"), "", errors);
  YamlSection model = root.section("model");
  std::string name;
  model.text("name", name, true);
  EXPECT_THAT(errors.messages(), ElementsAre("t.yaml:3: model.name: missing required key"));
}

TEST(YamlSection, NonMappingSectionIsAnError) {
  ErrorList errors("t.yaml");
  YamlSection root(YAML::Load("model: 5\n"), "", errors);
  YamlSection model = root.section("model");
  model.finish();
  EXPECT_THAT(errors.messages(),
              ElementsAre("t.yaml:1: model: expected a mapping of keys to values"));
}

TEST(YamlSection, NumbersChecksLengthAndElementRange) {
  ErrorList errors("t.yaml");
  YamlSection s(YAML::Load("ok: [1, 2]\nlong: [1, 2, 3, 4]\nneg: [1, -2]\nnone: []\n"), "", errors);
  std::vector<double> ok, too_long, negative, none;
  s.numbers("ok", ok, {2, 3});
  s.numbers("long", too_long, {2, 3});
  s.numbers("neg", negative, {}, Range::non_negative());
  s.numbers("none", none);
  EXPECT_THAT(ok, ElementsAre(1.0, 2.0));
  EXPECT_THAT(too_long, IsEmpty());
  EXPECT_THAT(errors.messages(),
              ElementsAre("t.yaml:2: long: expected a list of 2 or 3 numbers, got 4",
                          "t.yaml:3: neg: expected a list of numbers >= 0, got '-2' in it",
                          "t.yaml:4: none: expected a list of numbers, got an empty list"));
}

TEST(YamlSection, MatrixNeedsRowsOfEqualLength) {
  ErrorList errors("t.yaml");
  YamlSection s(YAML::Load("m: [[1, 0], [0, 1]]\nbad: [[1, 0], [1]]\n"), "", errors);
  std::vector<std::vector<double>> m, bad;
  s.matrix("m", m);
  s.matrix("bad", bad);
  EXPECT_EQ(m.size(), 2u);
  EXPECT_THAT(bad, IsEmpty());
  ASSERT_EQ(errors.messages().size(), 1u);
  EXPECT_THAT(errors.messages()[0], HasSubstr("t.yaml:2: bad: expected a list of rows"));
}

TEST(YamlSection, TextsReadsAListOfNames) {
  ErrorList errors("t.yaml");
  YamlSection s(YAML::Load("names: [cv, ct]\nnested: [[a]]\nscalar: cv\n"), "", errors);
  std::vector<std::string> names, nested, scalar;
  s.texts("names", names);
  s.texts("nested", nested);
  s.texts("scalar", scalar);
  EXPECT_THAT(names, ElementsAre("cv", "ct"));
  EXPECT_THAT(errors.messages(),
              ElementsAre("t.yaml:2: nested: expected a list of strings, got a list in it",
                          "t.yaml:3: scalar: expected a list of strings, got 'cv'"));
}

TEST(YamlSection, SectionsNameEachItemByIndex) {
  ErrorList errors("t.yaml");
  YamlSection root(YAML::Load("items:\n  - a: 1\n  - a: x\n"), "", errors);
  auto items = root.sections("items");
  ASSERT_EQ(items.size(), 2u);
  double a = 0.0;
  for (auto& item : items) item.number("a", a);
  EXPECT_THAT(errors.messages(),
              ElementsAre("t.yaml:3: items[1].a: expected a finite number, got 'x'"));
}

TEST(YamlSection, LoadYamlFileReportsMissingFilesAndSyntaxLines) {
  ErrorList missing("/nonexistent/p.yaml");
  EXPECT_FALSE(load_yaml_file("/nonexistent/p.yaml", missing));
  EXPECT_THAT(missing.messages(), ElementsAre("/nonexistent/p.yaml: cannot open file"));

  const std::string path = ::testing::TempDir() + "yaml_section_syntax.yaml";
  std::ofstream(path) << "a: 1\nb: [1, 2\nc: 3\n";
  ErrorList broken(path);
  EXPECT_FALSE(load_yaml_file(path, broken));
  EXPECT_THAT(broken.messages(), ElementsAre(path + ": line 3: end of sequence flow not found"));
}

}  // namespace
}  // namespace skytrack::config
