#pragma once
// The skytrackd configuration file (schema: docs/daemon.md): which tracking profile to run,
// the DDS domain, partition, topic names and QoS, the scan queue and its overload policy, and
// logging. Validated like the profiles: every mistake is reported at once as
// "file:line: key.path: what was expected", unknown keys included.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "skytrack/core/expected.hpp"

namespace skytrack::daemon {

enum class Reliability : std::uint8_t { kReliable, kBestEffort };
enum class Durability : std::uint8_t { kVolatile, kTransientLocal };
enum class OverloadPolicy : std::uint8_t { kDropOldest, kDropNewest };
enum class LogSink : std::uint8_t { kConsole, kFile };

struct TopicNames {
  std::string plots = "skytrack_plots";
  std::string tracks = "skytrack_tracks";
  std::string status = "skytrack_status";
};

struct PlotsQos {
  Reliability reliability = Reliability::kReliable;  // replay must not lose scans
  int history_depth = 0;                             // reader history per sensor; 0: keep all
};

struct TracksQos {
  Durability durability = Durability::kTransientLocal;  // a late display gets the picture
  int history_depth = 1;                                // kept per sensor for late joiners
};

struct StatusQos {
  double deadline = 3.0;  // [s] readers are told when a status is this late
};

struct DdsSettings {
  int domain = 0;
  std::vector<std::string> partitions;  // empty: the default partition
  TopicNames topics;
  PlotsQos plots;
  TracksQos tracks;
  StatusQos status;
};

struct QueueSettings {
  int capacity = 64;  // scans waiting for the tracker
  OverloadPolicy overload = OverloadPolicy::kDropOldest;
};

struct LogSettings {
  std::string level = "info";  // trace, debug, info, warn, error, critical, off
  LogSink sink = LogSink::kConsole;
  std::string file;      // for sink: file
  int max_size_mb = 10;  // per file before rotation
  int max_files = 5;     // rotated files kept
};

enum class InputMode : std::uint8_t { kDds, kAsterix, kBoth };

/// Live ASTERIX over UDP (docs/daemon.md, docs/asterix.md). The default binds a loopback
/// address: an external interface is only ever used when configured.
struct AsterixInput {
  std::string address = "127.0.0.1";    // unicast address to bind, or a multicast group
  int port = 8600;                      // 0: any free port (logged)
  std::string interface = "127.0.0.1";  // multicast: the local address to join the group on
  std::string source;                   // only datagrams from this address; empty: any
  std::string batch = "sector";         // sector, revolution or block:N
  std::string sensor;                   // only this SAC/SIC; empty: any
  bool keep_tests = false;              // keep SIM and TST reports
  double flush_after = 5.0;             // [s] without datagrams: close the open batches
  int receive_buffer_kb = 4096;         // SO_RCVBUF
};

struct InputSettings {
  InputMode mode = InputMode::kDds;
  AsterixInput asterix;
  bool dds() const { return mode != InputMode::kAsterix; }
  bool udp() const { return mode != InputMode::kDds; }
};

enum class Role : std::uint8_t {
  kTracker,  // PlotBatch in, the profile's Pipeline, TrackBatch out
  kFusion,   // local trackers' TrackBatch in, the fused picture out (docs/fusion.md)
};

/// The fusion role's inputs and outputs; its parameters are in a fusion file, the one
/// `skytrack fuse --config` reads, so the node and the offline tool fuse alike.
struct FusionRole {
  std::string config;                           // fusion file (resolved); empty: defaults
  std::string input_topic = "skytrack_tracks";  // the local trackers' TrackBatch
  std::string output_topic = "skytrack_fused";  // the fused TrackBatch
};

struct DaemonConfig {
  Role role = Role::kTracker;
  std::string instance = "skytrackd";  // TrackerStatus key
  std::string profile;                 // profile path (resolved); empty: built-in default
  std::vector<std::int64_t> sensors;   // accepted sensor ids (fusion: local trackers); empty: any
  int max_plots_per_scan = 100000;     // larger batches are rejected as absurd
  double status_period = 1.0;          // [s]
  // [s] batches dated further ahead of the host's UTC clock are refused; for sensors that
  // date their batches in UTC seconds since 1970. Absent: not checked.
  std::optional<double> max_ahead_of_host;
  InputSettings input;
  DdsSettings dds;
  QueueSettings queue;
  LogSettings logging;
  FusionRole fusion;  // role: fusion only
};

/// Reads and validates a daemon configuration file. A relative `profile` or `logging.file`
/// is resolved against the file's directory.
Expected<DaemonConfig> load_daemon_config(const std::string& path);

/// As load_daemon_config, from text; relative paths resolve against `base_dir`.
Expected<DaemonConfig> parse_daemon_config(const std::string& yaml_text,
                                           const std::string& name_for_messages,
                                           const std::string& base_dir);

std::string_view to_string(Reliability value);
std::string_view to_string(Durability value);
std::string_view to_string(OverloadPolicy value);
std::string_view to_string(InputMode value);
std::string_view to_string(Role value);

}  // namespace skytrack::daemon
