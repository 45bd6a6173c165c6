#include "skytrack/daemon/signal_pipe.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>

namespace skytrack::daemon {
namespace {

int pipe_fds[2] = {-1, -1};

extern "C" void on_signal(int signal) {
  const int saved = errno;
  const unsigned char byte = static_cast<unsigned char>(signal);
  [[maybe_unused]] const ssize_t n = write(pipe_fds[1], &byte, 1);  // full pipe: already woken
  errno = saved;
}

}  // namespace

Expected<void> SignalPipe::install(std::initializer_list<int> signals) {
  if (pipe_fds[0] < 0 && pipe2(pipe_fds, O_CLOEXEC | O_NONBLOCK) != 0) {
    return make_error(std::string("signal pipe: ") + std::strerror(errno));
  }
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (const int s : signals) {
    if (sigaction(s, &action, nullptr) != 0) {
      return make_error("signal " + std::to_string(s) + ": " + std::strerror(errno));
    }
  }
  std::signal(SIGPIPE, SIG_IGN);
  return {};
}

std::optional<int> SignalPipe::wait(std::chrono::milliseconds timeout) {
  if (pipe_fds[0] < 0) return std::nullopt;
  pollfd fd{pipe_fds[0], POLLIN, 0};
  const int ready = poll(&fd, 1, static_cast<int>(std::max<long long>(0, timeout.count())));
  if (ready <= 0) return std::nullopt;
  unsigned char byte = 0;
  if (read(pipe_fds[0], &byte, 1) != 1) return std::nullopt;
  return static_cast<int>(byte);
}

}  // namespace skytrack::daemon
