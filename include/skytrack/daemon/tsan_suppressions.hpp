#pragma once
// ThreadSanitizer suppressions for the DDS binaries (include in exactly one translation unit
// of each program that creates DDS entities). Debian's Cyclone DDS (libddsc) is not
// instrumented and synchronises its threads with its own atomics, which ThreadSanitizer
// cannot see, so it reports races between Cyclone's internal threads. Debian's spdlog
// (libspdlog, also not instrumented) releases shared_ptrs to sinks and formatters in its
// worker thread with atomics ThreadSanitizer cannot see, so the final release at shutdown is
// reported as a race. Only reports with a frame inside those two libraries are suppressed;
// races between skytrack's own threads (queue, status, reload hand-over) are still reported.
#if defined(__SANITIZE_THREAD__)
extern "C" const char* __tsan_default_suppressions() {
  return "race:libddsc.so\n"
         "called_from_lib:libddsc.so\n"
         "race:libspdlog.so\n";
}
#endif
