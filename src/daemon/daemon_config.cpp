// Daemon configuration loader: one reader per section, each calling finish() so unknown keys
// are errors. Schema: docs/daemon.md.
#include "skytrack/daemon/daemon_config.hpp"

#include <cmath>
#include <exception>
#include <filesystem>

#include <arpa/inet.h>

#include "skytrack/asterix/batcher.hpp"
#include "skytrack/asterix/records.hpp"
#include "skytrack/config/yaml_section.hpp"

namespace skytrack::daemon {
namespace {

using config::ErrorList;
using config::Range;
using config::YamlSection;

std::string resolve(const std::string& path, const std::string& base_dir) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (std::filesystem::path(base_dir) / path).lexically_normal().string();
}

void read_topics(YamlSection s, TopicNames& t) {
  s.text("plots", t.plots);
  s.text("tracks", t.tracks);
  s.text("status", t.status);
  for (const auto* key : {"plots", "tracks", "status"}) {
    const std::string& name = key[0] == 'p' ? t.plots : key[0] == 't' ? t.tracks : t.status;
    if (s.has(key) && name.empty()) s.error(key, "expected a non-empty topic name");
  }
  s.finish();
}

void read_qos(YamlSection s, DdsSettings& d) {
  YamlSection plots = s.section("plots");
  std::string reliability(to_string(d.plots.reliability));
  plots.choice("reliability", reliability, {"reliable", "best_effort"});
  d.plots.reliability =
      reliability == "best_effort" ? Reliability::kBestEffort : Reliability::kReliable;
  plots.integer("history_depth", d.plots.history_depth, Range{0.0, 100000.0});
  plots.finish();
  YamlSection tracks = s.section("tracks");
  std::string durability(to_string(d.tracks.durability));
  tracks.choice("durability", durability, {"transient_local", "volatile"});
  d.tracks.durability =
      durability == "volatile" ? Durability::kVolatile : Durability::kTransientLocal;
  tracks.integer("history_depth", d.tracks.history_depth, Range{1.0, 1000.0});
  tracks.finish();
  YamlSection status = s.section("status");
  status.number("deadline", d.status.deadline, Range::positive());
  status.finish();
  s.finish();
}

void read_dds(YamlSection s, DdsSettings& d) {
  s.integer("domain", d.domain, Range{0.0, 232.0});  // Cyclone: 0..232 on UDP
  if (s.has("partition")) {
    const YAML::Node node = s.node()["partition"];
    if (node.IsScalar()) {
      std::string one;
      s.text("partition", one);
      d.partitions = {one};
    } else {
      s.texts("partition", d.partitions);
    }
  }
  read_topics(s.section("topics"), d.topics);
  read_qos(s.section("qos"), d);
  s.finish();
}

void read_queue(YamlSection s, QueueSettings& q) {
  s.integer("capacity", q.capacity, Range{1.0, 100000.0});
  std::string policy(to_string(q.overload));
  s.choice("overload", policy, {"drop_oldest", "drop_newest"});
  q.overload = policy == "drop_newest" ? OverloadPolicy::kDropNewest : OverloadPolicy::kDropOldest;
  s.finish();
}

void read_input(YamlSection s, InputSettings& in) {
  std::string mode(to_string(in.mode));
  s.choice("from", mode, {"dds", "asterix", "both"});
  in.mode = mode == "asterix" ? InputMode::kAsterix
            : mode == "both"  ? InputMode::kBoth
                              : InputMode::kDds;
  YamlSection a = s.section("asterix");
  AsterixInput& u = in.asterix;
  a.text("address", u.address);
  a.integer("port", u.port, Range{0.0, 65535.0});
  a.text("interface", u.interface);
  a.text("source", u.source);
  a.text("batch", u.batch);
  a.text("sensor", u.sensor);
  a.boolean("keep_tests", u.keep_tests);
  a.number("flush_after", u.flush_after, Range{0.01, 3600.0});
  a.integer("receive_buffer_kb", u.receive_buffer_kb, Range{64.0, 1048576.0});
  if (a.has("batch") && !asterix::parse_batch_mode(u.batch)) {
    a.error("batch", "expected sector, revolution or block:N, got '" + u.batch + "'");
  }
  if (!u.sensor.empty() && !asterix::parse_sac_sic(u.sensor)) {
    a.error("sensor", "expected SAC/SIC (two numbers 0..255), got '" + u.sensor + "'");
  }
  for (const auto* key : {"address", "interface", "source"}) {
    const std::string& text = key[0] == 'a' ? u.address : key[0] == 'i' ? u.interface : u.source;
    in_addr probe{};
    if (a.has(key) && !(key[0] == 's' && text.empty()) &&
        inet_pton(AF_INET, text.c_str(), &probe) != 1) {
      a.error(key, "expected an IPv4 address, got '" + text + "'");
    }
  }
  a.finish();
  s.finish();
}

void read_logging(YamlSection s, LogSettings& l, const std::string& base_dir) {
  s.choice("level", l.level, {"trace", "debug", "info", "warn", "error", "critical", "off"});
  std::string sink = l.sink == LogSink::kFile ? "file" : "console";
  s.choice("sink", sink, {"console", "file"});
  l.sink = sink == "file" ? LogSink::kFile : LogSink::kConsole;
  s.text("file", l.file, l.sink == LogSink::kFile);
  l.file = resolve(l.file, base_dir);
  s.integer("max_size_mb", l.max_size_mb, Range{1.0, 100000.0});
  s.integer("max_files", l.max_files, Range{1.0, 1000.0});
  if (l.sink == LogSink::kConsole && s.has("file")) {
    s.error("file", "only used with sink: file");
  }
  s.finish();
}

void read_fusion(YamlSection s, FusionRole& f, const std::string& base_dir) {
  s.text("config", f.config);
  f.config = resolve(f.config, base_dir);
  s.text("input_topic", f.input_topic);
  s.text("output_topic", f.output_topic);
  for (const auto* key : {"input_topic", "output_topic"}) {
    const std::string& name = key[0] == 'i' ? f.input_topic : f.output_topic;
    if (s.has(key) && name.empty()) s.error(key, "expected a non-empty topic name");
  }
  if (f.input_topic == f.output_topic) {
    s.error("output_topic", "expected a topic other than input_topic ('" + f.input_topic +
                                "'): the node would fuse its own output");
  }
  s.finish();
}

DaemonConfig read_config(const YAML::Node& root, ErrorList& errors, const std::string& base_dir) {
  DaemonConfig c;
  YamlSection top(root, "", errors);
  YamlSection d = top.section("skytrackd");
  std::string role(to_string(c.role));
  d.choice("role", role, {"tracker", "fusion"});
  c.role = role == "fusion" ? Role::kFusion : Role::kTracker;
  if (c.role == Role::kFusion && d.has("profile")) {
    d.error("profile", "only used with role: tracker (the fusion role reads fusion.config)");
  }
  d.text("instance", c.instance);
  if (d.has("instance") && c.instance.empty()) d.error("instance", "expected a non-empty name");
  d.text("profile", c.profile);
  c.profile = resolve(c.profile, base_dir);
  std::vector<std::string> sensors;
  d.texts("sensors", sensors);
  for (const std::string& text : sensors) {
    std::size_t used = 0;
    long long id = -1;
    try {
      id = std::stoll(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text.size() || id < 0 || id > 4294967295LL) {
      d.error("sensors",
              "expected a list of sensor ids (integers 0..4294967295), got '" + text + "' in it");
      break;
    }
    c.sensors.push_back(id);
  }
  d.integer("max_plots_per_scan", c.max_plots_per_scan, Range{1.0, 10000000.0});
  d.number("status_period", c.status_period, Range{0.01, 3600.0});
  d.number("max_ahead_of_host", c.max_ahead_of_host, Range{0.0, 31536000.0});
  d.finish();
  read_input(top.section("input"), c.input);
  read_dds(top.section("dds"), c.dds);
  read_queue(top.section("queue"), c.queue);
  read_logging(top.section("logging"), c.logging, base_dir);
  if (top.has("fusion") && c.role != Role::kFusion) {
    top.error("fusion", "only used with skytrackd.role: fusion");
  }
  read_fusion(top.section("fusion"), c.fusion, base_dir);
  if (c.role == Role::kFusion && c.input.mode != InputMode::kDds) {
    top.error("input", "the fusion role takes TrackBatch over DDS only (input.from: dds)");
  }
  top.finish();
  if (errors.empty() && c.dds.status.deadline <= c.status_period) {
    errors.add(root["dds"]["qos"]["status"]["deadline"], "dds.qos.status.deadline",
               "expected more than skytrackd.status_period (" + std::to_string(c.status_period) +
                   " s), got " + std::to_string(c.dds.status.deadline));
  }
  return c;
}

Expected<DaemonConfig> build(const YAML::Node& node, ErrorList& errors,
                             const std::string& base_dir) {
  try {
    DaemonConfig c = read_config(node, errors, base_dir);
    if (errors.empty()) return c;
  } catch (const YAML::Exception& e) {
    errors.add(YAML::Node(), "", std::string("unexpected YAML error: ") + e.what());
  }
  return make_error(errors.joined());
}

}  // namespace

std::string_view to_string(Reliability value) {
  return value == Reliability::kBestEffort ? "best_effort" : "reliable";
}
std::string_view to_string(Durability value) {
  return value == Durability::kVolatile ? "volatile" : "transient_local";
}
std::string_view to_string(OverloadPolicy value) {
  return value == OverloadPolicy::kDropNewest ? "drop_newest" : "drop_oldest";
}

std::string_view to_string(InputMode value) {
  switch (value) {
    case InputMode::kAsterix:
      return "asterix";
    case InputMode::kBoth:
      return "both";
    case InputMode::kDds:
      break;
  }
  return "dds";
}

std::string_view to_string(Role value) {
  return value == Role::kFusion ? "fusion" : "tracker";
}

Expected<DaemonConfig> load_daemon_config(const std::string& path) {
  ErrorList errors(path);
  const auto node = config::load_yaml_file(path, errors);
  if (!node) return make_error(errors.joined());
  const std::string base = std::filesystem::absolute(path).parent_path().string();
  return build(*node, errors, base);
}

Expected<DaemonConfig> parse_daemon_config(const std::string& yaml_text,
                                           const std::string& name_for_messages,
                                           const std::string& base_dir) {
  ErrorList errors(name_for_messages);
  const auto node = config::parse_yaml_text(yaml_text, errors);
  if (!node) return make_error(errors.joined());
  return build(*node, errors, base_dir);
}

}  // namespace skytrack::daemon
