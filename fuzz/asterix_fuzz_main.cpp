// libFuzzer entry point (built with -DSKYTRACK_FUZZ=ON and clang; see docs/asterix.md).
#include <cstddef>
#include <cstdint>

int skytrack_asterix_fuzz_one(const std::uint8_t* data, std::size_t size);

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return skytrack_asterix_fuzz_one(data, size);
}
