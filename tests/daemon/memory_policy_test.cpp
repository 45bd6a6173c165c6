// apply_memory_policy: a scan's large buffers come from the heap and stay mapped when freed,
// so the next scan reuses them instead of faulting fresh pages in; the heap's reserve carries
// the kernel's huge-page advice.
#include "skytrack/daemon/memory_policy.hpp"

#include <gtest/gtest.h>
#include <malloc.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

// ASan and TSan own malloc: glibc's settings and heap are not theirs.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SKYTRACK_GLIBC_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define SKYTRACK_GLIBC_MALLOC 0
#endif
#endif
#ifndef SKYTRACK_GLIBC_MALLOC
#define SKYTRACK_GLIBC_MALLOC 1
#endif

namespace {

TEST(MemoryPolicy, LargeBlocksComeFromTheHeapAndStayMappedWhenFreed) {
  if (!SKYTRACK_GLIBC_MALLOC) GTEST_SKIP() << "a sanitizer owns malloc";
  ASSERT_TRUE(skytrack::daemon::apply_memory_policy().freed_memory_kept);
  // 8 MiB: far above glibc's default mmap threshold (128 KiB), below the policy's 32 MiB.
  constexpr std::size_t kBlock = 8u << 20;
  const struct mallinfo2 before = mallinfo2();
  void* block = std::malloc(kBlock);
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, kBlock);  // touched, as a scan's buffer is
  const struct mallinfo2 held = mallinfo2();
  EXPECT_EQ(held.hblks, before.hblks) << "the block was mapped on its own";
  std::free(block);
  const struct mallinfo2 after = mallinfo2();
  // Still in the heap, free for the next request: not trimmed back to the kernel.
  EXPECT_GE(after.arena, kBlock);
  EXPECT_GE(after.fordblks, kBlock);
}

TEST(MemoryPolicy, TheHeapIsAdvisedForHugePages) {
  if (!SKYTRACK_GLIBC_MALLOC) GTEST_SKIP() << "a sanitizer owns malloc";
  if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled")) {
    GTEST_SKIP() << "this kernel has no transparent huge pages";
  }
  ASSERT_TRUE(skytrack::daemon::apply_memory_policy().huge_page_heap);
  // /proc/self/smaps: the [heap] mapping's VmFlags carry "hg" (MADV_HUGEPAGE).
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool in_heap = false, advised = false;
  while (std::getline(smaps, line)) {
    if (line.find(" [heap]") != std::string::npos) in_heap = true;
    if (in_heap && line.rfind("VmFlags:", 0) == 0) {
      advised = advised || line.find(" hg") != std::string::npos;
      in_heap = false;
    }
  }
  EXPECT_TRUE(advised);
}

}  // namespace
