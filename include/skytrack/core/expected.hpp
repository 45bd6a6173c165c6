#pragma once
// Fallible boundary functions return Expected<T>. std::expected is C++23 and g++ 12 hides
// it under -std=c++20, so tl::expected stands in behind this alias.
#include <string>
#include <utility>

#include <tl/expected.hpp>

namespace skytrack {

/// A human-readable failure: what went wrong and where (file, line, key path).
struct Error {
  std::string message;
};

template <class T, class E = Error>
using Expected = tl::expected<T, E>;
using tl::unexpected;

inline unexpected<Error> make_error(std::string message) {
  return unexpected<Error>(Error{std::move(message)});
}

}  // namespace skytrack
