#pragma once
// A counting malloc for the allocation tests: include it in exactly one source file of a test
// program, which then replaces malloc for that program only. It forwards to glibc's
// allocator, so free, realloc and calloc (not replaced) stay consistent with it. While
// g_counting is set, every malloc in the process, library code included, is counted in
// g_allocations. glibc only, and not under ASan or TSan, which own malloc:
// SKYTRACK_COUNTING_MALLOC says whether it is in force (tests skip their count otherwise).
#include <atomic>
#include <cstddef>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SKYTRACK_COUNTING_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define SKYTRACK_COUNTING_MALLOC 0
#endif
#endif
#if !defined(SKYTRACK_COUNTING_MALLOC) && defined(__GLIBC__)
#define SKYTRACK_COUNTING_MALLOC 1
#endif
#ifndef SKYTRACK_COUNTING_MALLOC
#define SKYTRACK_COUNTING_MALLOC 0
#endif

#if SKYTRACK_COUNTING_MALLOC
namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace
extern "C" void* __libc_malloc(std::size_t size) noexcept;
extern "C" void* malloc(std::size_t size) noexcept {
  if (g_counting.load(std::memory_order_relaxed)) {
    g_allocations.fetch_add(1, std::memory_order_relaxed);
  }
  return __libc_malloc(size);
}
#endif
