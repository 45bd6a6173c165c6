#include "skytrack/daemon/logging.hpp"

#include <spdlog/async.h>
#include <spdlog/sinks/rotating_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace skytrack::daemon {

Expected<void> setup_logging(const LogSettings& settings) {
  try {
    spdlog::init_thread_pool(8192, 1);
    spdlog::sink_ptr sink;
    if (settings.sink == LogSink::kFile) {
      sink = std::make_shared<spdlog::sinks::rotating_file_sink_mt>(
          settings.file, static_cast<std::size_t>(settings.max_size_mb) * 1024 * 1024,
          static_cast<std::size_t>(settings.max_files));
    } else {
      sink = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
    }
    auto logger = std::make_shared<spdlog::async_logger>(
        "skytrackd", sink, spdlog::thread_pool(), spdlog::async_overflow_policy::overrun_oldest);
    logger->set_level(spdlog::level::from_str(settings.level));
    logger->set_pattern("%Y-%m-%d %H:%M:%S.%e %^%l%$ [%t] %v");
    logger->flush_on(spdlog::level::warn);
    spdlog::set_default_logger(logger);
    spdlog::flush_every(std::chrono::seconds(1));
  } catch (const spdlog::spdlog_ex& e) {
    return make_error(std::string("logging: ") + e.what());
  }
  return {};
}

void shutdown_logging() {
  spdlog::shutdown();
}

}  // namespace skytrack::daemon
