#pragma once
// How the tracking processes (skytrackd, skytrack) hold heap memory. A dense scan allocates
// tens of megabytes of plots, hypotheses and tentative tracks and frees them by the next.
// With glibc's defaults those blocks were mapped afresh or trimmed off the heap and grown
// again, scan after scan, and every 4 KiB page faulted in again: on the dense load
// (docs/peer-benchmark.md) about a seventh of the time per batch, more again in the faults of
// the heap's growth. So:
// - what a scan frees is kept for the next scan, not returned to the kernel (the resident
//   size stays at the busiest scan's, which a deployment provisions anyway);
// - all threads allocate from one heap (the daemon's tracking thread included), and its
//   reserve is advised for transparent huge pages: one fault per 2 MiB instead of 512 where
//   the kernel allows it (`/sys/kernel/mm/transparent_hugepage/enabled` `madvise` or
//   `always`; with `never` the advice is ignored and only the first point holds).

namespace skytrack::daemon {

struct MemoryPolicy {
  bool freed_memory_kept = false;  // the malloc settings were accepted
  bool huge_page_heap = false;     // the heap's reserve was advised for huge pages
};

/// Sets the process's malloc policy (glibc mallopt, madvise); call once at the start of
/// main, before any thread. Whatever is refused leaves the process on the C library's
/// defaults, slower but correct.
MemoryPolicy apply_memory_policy() noexcept;

}  // namespace skytrack::daemon
