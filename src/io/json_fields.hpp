#pragma once
// Typed, validating access to the fields of a simdjson DOM object. Every failure names the
// field path, so a rejected line says exactly what was wrong.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <simdjson.h>
#include <Eigen/Core>

#include "skytrack/core/expected.hpp"

namespace skytrack::io::detail {

using simdjson::dom::element;
using simdjson::dom::object;

inline std::string join(std::string_view path, std::string_view key) {
  if (path.empty()) return std::string(key);
  std::string out(path);
  out += '.';
  out += key;
  return out;
}

inline std::string indexed(std::string_view path, std::size_t index) {
  return std::string(path) + "[" + std::to_string(index) + "]";
}

/// The field `key` of `obj`, or nullopt when it is absent (or null).
inline std::optional<element> field(const object& obj, std::string_view key) {
  element value;
  if (obj.at_key(key).get(value) != simdjson::SUCCESS) return std::nullopt;
  if (value.is_null()) return std::nullopt;
  return value;
}

inline Expected<double> as_finite(const element& value, const std::string& path) {
  double number = 0.0;
  if (value.get_double().get(number) != simdjson::SUCCESS) {
    return make_error(path + ": expected a number");
  }
  if (!std::isfinite(number)) return make_error(path + ": not finite");
  return number;
}

inline Expected<std::int64_t> as_integer(const element& value, const std::string& path) {
  std::int64_t number = 0;
  if (value.get_int64().get(number) == simdjson::SUCCESS) return number;
  // Accept integral doubles such as 42.0 written by tools that only know doubles.
  double real = 0.0;
  if (value.get_double().get(real) == simdjson::SUCCESS && std::isfinite(real) &&
      real == std::floor(real) && std::abs(real) < 9.0e15) {
    return static_cast<std::int64_t>(real);
  }
  return make_error(path + ": expected an integer");
}

inline Expected<object> as_object(const element& value, const std::string& path) {
  object obj;
  if (value.get_object().get(obj) != simdjson::SUCCESS) {
    return make_error(path + ": expected an object");
  }
  return obj;
}

inline Expected<simdjson::dom::array> as_array(const element& value, const std::string& path) {
  simdjson::dom::array arr;
  if (value.get_array().get(arr) != simdjson::SUCCESS) {
    return make_error(path + ": expected an array");
  }
  return arr;
}

inline Expected<std::string_view> as_string(const element& value, const std::string& path) {
  std::string_view text;
  if (value.get_string().get(text) != simdjson::SUCCESS) {
    return make_error(path + ": expected a string");
  }
  return text;
}

/// A required field, read with `get` (one of the as_* functions below or above).
template <class T, class Get>
Expected<T> required(const object& obj, std::string_view path, std::string_view key, Get get) {
  const auto value = field(obj, key);
  const std::string full = join(path, key);
  if (!value) return make_error(full + ": missing required field");
  return get(*value, full);
}

/// An optional field: nullopt when absent, an error when present but invalid.
template <class T, class Get>
Expected<std::optional<T>> optional_field(const object& obj, std::string_view path,
                                          std::string_view key, Get get) {
  const auto value = field(obj, key);
  if (!value) return std::optional<T>{};
  Expected<T> parsed = get(*value, join(path, key));
  if (!parsed) return unexpected(parsed.error());
  return std::optional<T>{*parsed};
}

/// A 2- or 3-component vector of finite numbers; `dims` receives the count.
inline Expected<Eigen::Vector3d> as_vector23(const element& value, const std::string& path,
                                             int* dims = nullptr) {
  auto arr = as_array(value, path);
  if (!arr) return unexpected(arr.error());
  const std::size_t size = arr->size();
  if (size != 2 && size != 3) return make_error(path + ": expected 2 or 3 numbers");
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  std::size_t i = 0;
  for (element item : *arr) {
    auto number = as_finite(item, indexed(path, i));
    if (!number) return unexpected(number.error());
    out[static_cast<Eigen::Index>(i++)] = *number;
  }
  if (dims) *dims = static_cast<int>(size);
  return out;
}

/// A symmetric positive-definite 2x2 matrix given as [[a, b], [c, d]].
inline Expected<Eigen::Matrix2d> as_extent(const element& value, const std::string& path) {
  auto rows = as_array(value, path);
  if (!rows || rows->size() != 2) return make_error(path + ": expected a 2x2 array");
  Eigen::Matrix2d m;
  int r = 0;
  for (element row : *rows) {
    auto cols = as_array(row, indexed(path, r));
    if (!cols || cols->size() != 2) return make_error(path + ": expected a 2x2 array");
    int c = 0;
    for (element item : *cols) {
      auto number = as_finite(item, indexed(indexed(path, r), c));
      if (!number) return unexpected(number.error());
      m(r, c++) = *number;
    }
    ++r;
  }
  const double asym = std::abs(m(0, 1) - m(1, 0));
  if (asym > 1e-9 * (1.0 + m.cwiseAbs().maxCoeff())) return make_error(path + ": not symmetric");
  if (!(m(0, 0) > 0.0) || !(m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0) > 0.0)) {
    return make_error(path + ": not positive definite");
  }
  return m;
}

}  // namespace skytrack::io::detail
