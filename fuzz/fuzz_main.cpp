// libFuzzer entry point of one fuzz target, chosen at build time (fuzz/CMakeLists.txt defines
// SKYTRACK_FUZZ_TARGET as the target's function; docs/hardening.md runs them).
#include <cstddef>
#include <cstdint>

#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return SKYTRACK_FUZZ_TARGET(data, size);
}
