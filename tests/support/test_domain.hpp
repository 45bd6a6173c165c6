// A DDS domain id held by one test process while it runs. ctest -j runs tests in parallel,
// each in a process of its own, and two tests on one domain see each other's samples (a
// daemon takes the other test's scans as out of order). A process id modulo the range left
// that to chance; here each id is leased by an exclusive lock on a file named after it, which
// the kernel releases when the process ends, however it ends. Domains 220..232 stay with the
// tests that fix theirs (the ASTERIX input's and the C clients').
#pragma once

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace skytrack::test {

class TestDomain {
 public:
  static constexpr int kFirst = 1;
  static constexpr int kCount = 219;  // 1..219

  /// Leases the first free id from one derived from the process id (so that tests started
  /// together try different ids first). If every id is taken (219 tests at once), the
  /// derived id is used unleased.
  TestDomain() {
    const int start = static_cast<int>(getpid() % kCount);
    id_ = kFirst + start;
    for (int i = 0; i < kCount; ++i) {
      const int id = kFirst + (start + i) % kCount;
      const std::string lock = (std::filesystem::temp_directory_path() /
                                ("skytrack-test-dds-domain-" + std::to_string(id) + ".lock"))
                                   .string();
      const int fd = ::open(lock.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0666);
      if (fd < 0) continue;
      if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
        fd_ = fd;
        id_ = id;
        return;
      }
      ::close(fd);
    }
  }
  ~TestDomain() {
    if (fd_ >= 0) ::close(fd_);
  }
  TestDomain(const TestDomain&) = delete;
  TestDomain& operator=(const TestDomain&) = delete;

  int id() const { return id_; }

 private:
  int id_ = 0;
  int fd_ = -1;
};

}  // namespace skytrack::test
