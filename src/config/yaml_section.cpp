#include "skytrack/config/yaml_section.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace skytrack::config {

void ErrorList::add(const YAML::Node& where, std::string_view path, std::string_view message) {
  std::ostringstream out;
  out << file_;
  if (where.IsDefined() && where.Mark().line >= 0) out << ":" << where.Mark().line + 1;
  out << ": ";
  if (!path.empty()) out << path << ": ";
  out << message;
  messages_.push_back(out.str());
}

std::string ErrorList::joined() const {
  std::string out;
  for (const auto& message : messages_) {
    if (!out.empty()) out += '\n';
    out += message;
  }
  return out;
}

bool Range::contains(double value) const {
  if (min_exclusive ? !(value > min) : !(value >= min)) return false;
  if (max_exclusive ? !(value < max) : !(value <= max)) return false;
  return true;
}

std::string Range::describe() const {
  std::ostringstream out;
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max) {
    out << "in " << (min_exclusive ? "(" : "[") << min << ", " << max
        << (max_exclusive ? ")" : "]");
  } else if (has_min) {
    out << (min_exclusive ? "> " : ">= ") << min;
  } else if (has_max) {
    out << (max_exclusive ? "< " : "<= ") << max;
  } else {
    out << "finite";
  }
  return out.str();
}

YamlSection::YamlSection(YAML::Node node, std::string path, ErrorList& errors)
    : node_(std::move(node)), path_(std::move(path)), errors_(&errors) {
  if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap()) {
    errors_->add(node_, path_, "expected a mapping of keys to values");
    node_ = YAML::Node();
  }
}

std::string YamlSection::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void YamlSection::error(std::string_view key, std::string_view message) {
  const std::string k(key);
  const YAML::Node where = (node_.IsMap() && node_[k]) ? node_[k] : node_;
  errors_->add(where, key_path(key), message);
}

bool YamlSection::has(std::string_view key) const {
  return node_.IsMap() && node_[std::string(key)].IsDefined();
}

std::optional<YAML::Node> YamlSection::take(std::string_view key, bool required) {
  consumed_.emplace_back(key);
  if (!has(key)) {
    if (required) errors_->add(node_, key_path(key), "missing required key");
    return std::nullopt;
  }
  return node_[std::string(key)];
}

namespace {

// What a node holds, for "got ..." in messages.
std::string found(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return node.size() == 0 ? "an empty list" : "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

// "expected a number >= 0"; an unbounded range adds nothing.
std::string expecting(const std::string& what, const Range& range) {
  const bool bounded = std::isfinite(range.min) || std::isfinite(range.max);
  return "expected " + what + (bounded ? " " + range.describe() : std::string());
}

std::optional<double> as_double(const YAML::Node& node) {
  if (!node.IsScalar()) return std::nullopt;
  double value = 0.0;
  if (!YAML::convert<double>::decode(node, value) || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

void YamlSection::number(std::string_view key, double& out, Range range, bool required) {
  const auto node = take(key, required);
  if (!node) return;
  const auto value = as_double(*node);
  if (!value) return error(key, expecting("a finite number", range) + ", got " + found(*node));
  if (!range.contains(*value)) {
    std::ostringstream got;
    got << *value;
    return error(key, expecting("a number", range) + ", got " + got.str());
  }
  out = *value;
}

void YamlSection::number(std::string_view key, std::optional<double>& out, Range range) {
  double value = 0.0;
  const std::size_t before = errors_->messages().size();
  if (!has(key)) {
    consumed_.emplace_back(key);
    return;
  }
  number(key, value, range, true);
  if (errors_->messages().size() == before) out = value;
}

void YamlSection::integer(std::string_view key, std::int64_t& out, Range range, bool required) {
  const auto node = take(key, required);
  if (!node) return;
  const auto value = as_double(*node);
  if (!value || *value != std::floor(*value) || std::abs(*value) > 9e15) {
    return error(key, expecting("an integer", range) + ", got " + found(*node));
  }
  if (!range.contains(*value)) {
    return error(key, expecting("an integer", range) + ", got " +
                          std::to_string(static_cast<std::int64_t>(*value)));
  }
  out = static_cast<std::int64_t>(*value);
}

void YamlSection::integer(std::string_view key, int& out, Range range, bool required) {
  // Check the int limits after reading, so that messages show the caller's range only.
  std::int64_t value = out;
  const std::size_t before = errors_->messages().size();
  integer(key, value, range, required);
  if (errors_->messages().size() != before) return;
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
    return error(key, "expected a 32-bit integer, got " + std::to_string(value));
  }
  out = static_cast<int>(value);
}

void YamlSection::boolean(std::string_view key, bool& out) {
  const auto node = take(key, false);
  if (!node) return;
  bool value = false;
  if (!node->IsScalar() || !YAML::convert<bool>::decode(*node, value)) {
    return error(key, "expected true or false, got " + found(*node));
  }
  out = value;
}

void YamlSection::text(std::string_view key, std::string& out, bool required) {
  const auto node = take(key, required);
  if (!node) return;
  if (!node->IsScalar()) return error(key, "expected a string, got " + found(*node));
  out = node->Scalar();
}

void YamlSection::texts(std::string_view key, std::vector<std::string>& out, bool required) {
  const auto node = take(key, required);
  if (!node) return;
  if (!node->IsSequence()) return error(key, "expected a list of strings, got " + found(*node));
  std::vector<std::string> values;
  for (const auto& item : *node) {
    if (!item.IsScalar()) {
      return error(key, "expected a list of strings, got " + found(item) + " in it");
    }
    values.push_back(item.Scalar());
  }
  out = std::move(values);
}

void YamlSection::choice(std::string_view key, std::string& out,
                         std::initializer_list<std::string_view> allowed, bool required) {
  std::string value;
  const std::size_t before = errors_->messages().size();
  text(key, value, required);
  if (errors_->messages().size() != before || !has(key)) return;
  if (std::find(allowed.begin(), allowed.end(), value) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    return error(key, "expected one of " + list + ", got '" + value + "'");
  }
  out = value;
}

void YamlSection::numbers(std::string_view key, std::vector<double>& out,
                          std::initializer_list<int> sizes, Range range, bool required) {
  const auto node = take(key, required);
  if (!node) return;
  std::string size_text;
  for (int s : sizes) size_text += (size_text.empty() ? "" : " or ") + std::to_string(s);
  const std::string what =
      "a list of " + (size_text.empty() ? std::string("") : size_text + " ") + "numbers";
  if (!node->IsSequence() || node->size() == 0) {
    return error(key, "expected " + what + ", got " + found(*node));
  }
  if (sizes.size() &&
      std::find(sizes.begin(), sizes.end(), static_cast<int>(node->size())) == sizes.end()) {
    return error(key, "expected " + what + ", got " + std::to_string(node->size()));
  }
  std::vector<double> values;
  for (const auto& item : *node) {
    const auto value = as_double(item);
    if (!value || !range.contains(*value)) {
      return error(key, expecting(what, range) + ", got " + found(item) + " in it");
    }
    values.push_back(*value);
  }
  out = std::move(values);
}

void YamlSection::matrix(std::string_view key, std::vector<std::vector<double>>& out,
                         bool required) {
  const auto node = take(key, required);
  if (!node) return;
  const char* expected = "expected a list of rows, each a list of numbers of equal length";
  if (!node->IsSequence() || node->size() == 0) return error(key, expected);
  std::vector<std::vector<double>> rows;
  for (const auto& row : *node) {
    if (!row.IsSequence() || row.size() == 0) return error(key, expected);
    std::vector<double> values;
    for (const auto& item : row) {
      const auto value = as_double(item);
      if (!value) return error(key, expected);
      values.push_back(*value);
    }
    if (!rows.empty() && values.size() != rows.front().size()) return error(key, expected);
    rows.push_back(std::move(values));
  }
  out = std::move(rows);
}

YamlSection YamlSection::section(std::string_view key, bool required) {
  const auto node = take(key, required);
  return YamlSection(node.value_or(YAML::Node()), key_path(key), *errors_);
}

std::vector<YamlSection> YamlSection::sections(std::string_view key, bool required) {
  std::vector<YamlSection> out;
  const auto node = take(key, required);
  if (!node) return out;
  if (!node->IsSequence()) {
    error(key, "expected a list of mappings");
    return out;
  }
  for (std::size_t i = 0; i < node->size(); ++i) {
    out.emplace_back((*node)[i], key_path(key) + "[" + std::to_string(i) + "]", *errors_);
  }
  return out;
}

void YamlSection::finish() {
  if (!node_.IsMap()) return;
  std::vector<std::string> seen;
  for (const auto& item : node_) {
    const std::string key = item.first.as<std::string>("");
    // yaml-cpp keeps duplicate keys and readers see only the first: say so.
    if (std::find(seen.begin(), seen.end(), key) != seen.end()) {
      errors_->add(item.first, key_path(key), "duplicate key (only the first is used)");
      continue;
    }
    seen.push_back(key);
    if (std::find(consumed_.begin(), consumed_.end(), key) != consumed_.end()) continue;
    std::string known;
    for (const auto& k : consumed_) known += (known.empty() ? "" : ", ") + k;
    errors_->add(item.first, key_path(key), "unknown key (known keys here: " + known + ")");
  }
}

std::optional<YAML::Node> load_yaml_file(const std::string& path, ErrorList& errors) {
  try {
    return YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    errors.add(YAML::Node(), "", "cannot open file");
  } catch (const YAML::ParserException& e) {
    errors.add(YAML::Node(), "", "line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  return std::nullopt;
}

std::optional<YAML::Node> parse_yaml_text(const std::string& text, ErrorList& errors) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    errors.add(YAML::Node(), "", "line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  return std::nullopt;
}

}  // namespace skytrack::config
