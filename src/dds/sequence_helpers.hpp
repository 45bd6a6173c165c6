#pragma once
// Helpers shared by the DDS conversions: sequence allocation that dds_sample_free can release,
// strings, and field names for error messages.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <dds/dds.h>
#include <Eigen/Core>

#include "skytrack/core/expected.hpp"

namespace skytrack::dds::detail {

inline constexpr std::uint32_t kMaxSequence = std::numeric_limits<std::uint32_t>::max();
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

inline std::string field(std::string_view base, std::size_t index, std::string_view member) {
  std::string out(base);
  out += '[';
  out += std::to_string(index);
  out += "].";
  out += member;
  return out;
}

// ---- allocation -----------------------------------------------------------------------------

/// Gives `seq` exactly n zeroed elements (struct and string sequences: every element up to
/// _maximum must be valid for dds_sample_free). Returns false when out of memory.
template <class Seq>
bool alloc_zeroed(Seq& seq, std::size_t n) {
  using Elem = std::remove_pointer_t<decltype(seq._buffer)>;
  seq._buffer = nullptr;
  seq._maximum = seq._length = 0;
  seq._release = true;
  if (n == 0) return true;
  seq._buffer = static_cast<Elem*>(dds_alloc(n * sizeof(Elem)));
  if (seq._buffer == nullptr) return false;
  seq._maximum = seq._length = static_cast<std::uint32_t>(n);
  return true;
}

/// Gives a primitive sequence room for n elements, reusing its buffer when large enough.
/// The contents are left uninitialised: the caller overwrites all n.
template <class Seq>
bool reserve_primitive(Seq& seq, std::size_t n) {
  using Elem = std::remove_pointer_t<decltype(seq._buffer)>;
  if (seq._maximum < n || (seq._buffer == nullptr && n > 0)) {
    if (seq._release) dds_free(seq._buffer);
    seq._buffer = static_cast<Elem*>(dds_realloc(nullptr, n * sizeof(Elem)));
    seq._maximum = seq._buffer != nullptr ? static_cast<std::uint32_t>(n) : 0;
    seq._release = true;
    if (seq._buffer == nullptr) {
      seq._length = 0;
      return false;
    }
  }
  seq._length = static_cast<std::uint32_t>(n);
  return true;
}

/// A DDS copy of `text`, or an error naming `what` when the text cannot travel as a string.
inline Expected<char*> dup_string(std::string_view text, std::string_view what) {
  if (text.find('\0') != std::string_view::npos) {
    return make_error(std::string(what) + ": contains a NUL character");
  }
  char* out = dds_string_alloc(text.size());
  if (out == nullptr) return make_error(std::string(what) + ": out of memory");
  std::memcpy(out, text.data(), text.size());
  out[text.size()] = '\0';
  return out;
}

inline Error out_of_memory(std::string_view what) {
  return Error{std::string(what) + ": out of memory"};
}

inline std::string from_c_string(const char* text) {
  return text != nullptr ? std::string(text) : "";
}

/// An error when a received sequence claims elements but carries no buffer.
template <class Seq>
std::optional<Error> missing_buffer(const Seq& seq, std::string_view what) {
  if (seq._length == 0 || seq._buffer != nullptr) return std::nullopt;
  return Error{std::string(what) + ": length " + std::to_string(seq._length) + " without a buffer"};
}

inline void copy3(const Eigen::Vector3d& from, double (&to)[3]) {
  to[0] = from.x();
  to[1] = from.y();
  to[2] = from.z();
}

inline Eigen::Vector3d vector3(const double (&from)[3]) {
  return {from[0], from[1], from[2]};
}

}  // namespace skytrack::dds::detail
