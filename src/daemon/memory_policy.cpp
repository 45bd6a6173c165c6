#include "skytrack/daemon/memory_policy.hpp"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <climits>
#include <cstdint>
#include <cstdlib>

namespace skytrack::daemon {
namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
// Blocks up to glibc's largest mmap threshold on 64-bit come from the heap.
constexpr int kLargestHeapBlock = 32 << 20;
// Address space the heap takes at once when it first grows: a dense scan's working set fits
// (the 500 / 5 000 load peaks near 80 MiB resident). Only touched pages become resident.
constexpr int kHeapReserve = 256 << 20;

bool advise_heap_reserve() noexcept {
  // Grow the heap by its reserve now (a block below the mmap threshold, plus the top pad),
  // keep it (trimming is off), and advise the whole range from that block's start to the
  // break for huge pages.
  if (mallopt(M_TOP_PAD, kHeapReserve) != 1) return false;
  void* block = std::malloc(kLargestHeapBlock - 4096);
  const auto begin = reinterpret_cast<std::uintptr_t>(block);
  const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0));
  std::free(block);
  mallopt(M_TOP_PAD, 0);  // later growth (past the reserve) by what is asked
  // A heap that is not contiguous below the break (sbrk refused, glibc mapped instead) is
  // left alone.
  if (block == nullptr || end <= begin || end - begin < kHugePage + kLargestHeapBlock) {
    return false;
  }
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  return madvise(reinterpret_cast<void*>(first), end - first, MADV_HUGEPAGE) == 0;
}

}  // namespace

MemoryPolicy apply_memory_policy() noexcept {
  MemoryPolicy policy;
  const bool heap = mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock) == 1;
  const bool kept = mallopt(M_TRIM_THRESHOLD, INT_MAX) == 1;
  const bool one_heap = mallopt(M_ARENA_MAX, 1) == 1;
  policy.freed_memory_kept = heap && kept;
  policy.huge_page_heap = policy.freed_memory_kept && one_heap && advise_heap_reserve();
  return policy;
}

}  // namespace skytrack::daemon
