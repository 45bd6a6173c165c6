// `skytrack status`: prints the latest TrackerStatus of every running daemon as one JSON
// object per line (transient-local: a status published before we joined arrives at once).
#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "commands.hpp"
#include "dds_tool.hpp"
#include "skytrack/daemon/dds_session.hpp"
#include "skytrack/dds/checked_take.hpp"
#include "skytrack/dds/conversion.hpp"

namespace skytrack::tool {
namespace {

struct StatusOptions {
  DdsToolOptions dds;
  double wait = 5.0;  // [s]
  double follow = 0.0;
};

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += fmt::format("\\u{:04x}", static_cast<unsigned char>(c));
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string json_counts(const std::vector<RejectionCount>& counts) {
  std::string out = "{";
  for (const auto& c : counts) {
    out += (out.size() > 1 ? ", " : "") + json_string(c.reason) + ": " + std::to_string(c.count);
  }
  return out + "}";
}

std::string status_to_json(const TrackerStatusReport& s) {
  return fmt::format(
      "{{\"instance\": {}, \"profile\": {{\"name\": {}, \"version\": {}}}, \"uptime\": {:.3f}, "
      "\"scans_processed\": {}, \"plots_processed\": {}, \"plots_rejected\": {}, "
      "\"scans_rejected\": {}, \"scans_dropped\": {}, \"queue_depth\": {}, "
      "\"latency\": {{\"p50\": {:.6g}, \"p99\": {:.6g}, \"max\": {:.6g}}}, "
      "\"tracks\": {{\"tentative\": {}, \"confirmed\": {}, \"coasting\": {}}}, "
      "\"numeric_failures\": {}}}",
      json_string(s.instance), json_string(s.profile_name), json_string(s.profile_version),
      s.uptime, s.scans_processed, s.plots_processed, json_counts(s.plots_rejected),
      json_counts(s.scans_rejected), s.scans_dropped, s.queue_depth, s.latency_p50, s.latency_p99,
      s.latency_max, s.tracks_tentative, s.tracks_confirmed, s.tracks_coasting, s.numeric_failures);
}

int run_status(const StatusOptions& options) {
  auto config = resolve_dds_tool_config(options.dds);
  if (!config) {
    fmt::print(stderr, "{}\n", config.error().message);
    return 2;
  }
  auto session = open_tool_session(config->dds, "status");
  if (!session) {
    fmt::print(stderr, "{}\n", session.error().message);
    return 2;
  }
  auto topic = session->topic(&skytrack_dds_TrackerStatus_desc, config->dds.topics.status);
  if (!topic) {
    fmt::print(stderr, "skytrack status: {}\n", topic.error().message);
    return 2;
  }
  auto reader = session->reader(*topic, daemon::status_reader_qos(config->dds).get());
  if (!reader) {
    fmt::print(stderr, "skytrack status: {}\n", reader.error().message);
    return 2;
  }
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto wait = std::chrono::duration<double>(options.wait);
  const auto follow = std::chrono::duration<double>(options.follow);
  std::map<std::string, TrackerStatusReport> latest;
  dds::TrackerStatusSample sample;
  while (!stop_requested()) {
    dds::take_checked(
        *reader, sample,
        [&](const skytrack_dds_TrackerStatus& s, const dds_sample_info_t&) {
          auto report = dds::from_dds(s);
          if (!report) return;
          if (options.follow > 0.0) fmt::print("{}\n", status_to_json(*report));
          latest[report->instance] = std::move(*report);
        },
        [](const dds_sample_info_t&, const Error& e) {
          fmt::print(stderr, "skytrack status: malformed sample refused: {}\n", e.message);
        });
    dds_requested_deadline_missed_status_t missed{};
    if (options.follow > 0.0 &&
        dds_get_requested_deadline_missed_status(*reader, &missed) == DDS_RETCODE_OK &&
        missed.total_count_change > 0) {
      fmt::print(stderr,
                 "skytrack status: deadline missed: no TrackerStatus for {} s ({} in all)\n",
                 config->dds.status.deadline, missed.total_count);
    }
    std::fflush(stdout);
    const auto elapsed = Clock::now() - start;
    if (options.follow > 0.0 ? elapsed > follow : (!latest.empty() || elapsed > wait)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (options.follow > 0.0) return 0;
  if (latest.empty()) {
    fmt::print(stderr, "skytrack status: no TrackerStatus on '{}' (domain {}) within {} s\n",
               config->dds.topics.status, config->dds.domain, options.wait);
    return 3;
  }
  for (const auto& [instance, report] : latest) fmt::print("{}\n", status_to_json(report));
  return 0;
}

}  // namespace

void add_status_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<StatusOptions>();
  CLI::App* cmd =
      app.add_subcommand("status", "Print the running daemons' latest TrackerStatus as JSON (DDS)");
  cmd->add_option("--wait", options->wait, "Seconds to wait for a status")->default_val(5.0);
  cmd->add_option("--follow", options->follow,
                  "Print every status sample for this many seconds instead, and each missed "
                  "deadline (a daemon gone quiet)");
  add_dds_options(*cmd, options->dds);
  cmd->footer(
      "Example: skytrack status --config config/skytrackd.yaml\nExit codes: 0 printed "
      "(or --follow ran its time); 2 the configuration or DDS failed; 3 no "
      "TrackerStatus within --wait; 1xx command-line mistakes (CLI11: 105 a bad value, "
      "106 a required option missing, 109 an unknown argument).");
  cmd->callback([options, &exit_code] { exit_code = run_status(*options); });
}

}  // namespace skytrack::tool
