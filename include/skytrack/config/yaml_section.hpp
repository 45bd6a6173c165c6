#pragma once
// Validating reader over one YAML mapping. Each read names the key it consumes; finish()
// reports every key nobody read as unknown. All problems are collected (not thrown), each as
// "file:line: key.path: what was expected", so a user sees every mistake of a file at once.
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace skytrack::config {

/// Errors collected while reading one file.
class ErrorList {
 public:
  explicit ErrorList(std::string file) : file_(std::move(file)) {}
  void add(const YAML::Node& where, std::string_view path, std::string_view message);
  bool empty() const { return messages_.empty(); }
  const std::vector<std::string>& messages() const { return messages_; }
  std::string joined() const;  // one message per line
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::vector<std::string> messages_;
};

/// An inclusive or exclusive numeric interval for validation.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  bool max_exclusive = false;

  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range non_negative() { return {0.0}; }
  static Range probability() { return {0.0, 1.0}; }
  static Range open_probability() { return {0.0, 1.0, true, false}; }
  bool contains(double value) const;
  std::string describe() const;
};

class YamlSection {
 public:
  /// `node` must be a map (or absent/null, meaning empty); `path` is its key path.
  YamlSection(YAML::Node node, std::string path, ErrorList& errors);

  bool has(std::string_view key) const;
  const std::string& path() const { return path_; }
  const YAML::Node& node() const { return node_; }

  // Each reader leaves `out` unchanged when the key is absent and not required.
  void number(std::string_view key, double& out, Range range = {}, bool required = false);
  void number(std::string_view key, std::optional<double>& out, Range range = {});
  void integer(std::string_view key, std::int64_t& out, Range range = {}, bool required = false);
  void integer(std::string_view key, int& out, Range range = {}, bool required = false);
  void boolean(std::string_view key, bool& out);
  void text(std::string_view key, std::string& out, bool required = false);
  /// A list of strings (e.g. names referring to other entries).
  void texts(std::string_view key, std::vector<std::string>& out, bool required = false);
  /// A string from a closed set.
  void choice(std::string_view key, std::string& out,
              std::initializer_list<std::string_view> allowed, bool required = false);
  /// A list of numbers; `sizes` lists the accepted lengths (empty: any non-empty length).
  void numbers(std::string_view key, std::vector<double>& out,
               std::initializer_list<int> sizes = {}, Range range = {}, bool required = false);
  /// A list of lists of numbers (a matrix), every row of the same length.
  void matrix(std::string_view key, std::vector<std::vector<double>>& out, bool required = false);

  /// A nested map; absent gives an empty section.
  YamlSection section(std::string_view key, bool required = false);
  /// A list of maps.
  std::vector<YamlSection> sections(std::string_view key, bool required = false);

  /// Reports keys that no reader consumed.
  void finish();

  void error(std::string_view key, std::string_view message);

 private:
  std::optional<YAML::Node> take(std::string_view key, bool required);
  std::string key_path(std::string_view key) const;

  YAML::Node node_;
  std::string path_;
  ErrorList* errors_;
  std::vector<std::string> consumed_;
};

/// Loads a YAML file; a syntax error is reported with its line.
std::optional<YAML::Node> load_yaml_file(const std::string& path, ErrorList& errors);
/// Parses YAML text; a syntax error is reported with its line, as load_yaml_file does.
std::optional<YAML::Node> parse_yaml_text(const std::string& text, ErrorList& errors);

}  // namespace skytrack::config
