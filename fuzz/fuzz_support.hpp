#pragma once
// What the fuzz targets share: an invariant check that names itself before it aborts (so a
// libFuzzer crash report, or a failing corpus test, says which promise broke), and a reader
// that takes typed values from the fuzz bytes, zeros once they run out.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <type_traits>

namespace skytrack::fuzz {

[[noreturn]] inline void fail(const char* what, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: fuzz invariant broken: %s\n", file, line, what);
  std::abort();
}

/// Takes trivially copyable values off the front of the fuzz input; past its end every value
/// is zero, so any input, however short, is a complete one.
class FuzzInput {
 public:
  explicit FuzzInput(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  template <class T>
  T take() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value{};
    const std::size_t n = sizeof(T) < bytes_.size() ? sizeof(T) : bytes_.size();
    if (n > 0) std::memcpy(&value, bytes_.data(), n);
    bytes_ = bytes_.subspan(n);
    return value;
  }
  std::uint8_t byte() { return take<std::uint8_t>(); }
  bool empty() const { return bytes_.empty(); }
  std::size_t remaining() const { return bytes_.size(); }

 private:
  std::span<const std::uint8_t> bytes_;
};

}  // namespace skytrack::fuzz

#define SKYTRACK_FUZZ_CHECK(condition) \
  ((condition) ? void(0) : ::skytrack::fuzz::fail(#condition, __FILE__, __LINE__))
