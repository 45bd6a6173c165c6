#pragma once
// A DDS participant with one publisher and one subscriber in the configured partitions, and
// the QoS of each skytrack topic (docs/daemon.md, "QoS"). The participant (and everything
// created under it) is deleted by the destructor, from normal code.
#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include <dds/dds.h>

#include "skytrack/core/expected.hpp"
#include "skytrack/daemon/daemon_config.hpp"

namespace skytrack::daemon {

struct QosDeleter {
  void operator()(dds_qos_t* qos) const { dds_delete_qos(qos); }
};
using QosPtr = std::unique_ptr<dds_qos_t, QosDeleter>;

// Plots: reliability from the config (reliable by default); the writer keeps all samples so
// a replay is flow-controlled rather than lossy; the reader keeps all (or history_depth per
// sensor). Volatile: an old scan is of no use to a tracker.
QosPtr plots_reader_qos(const DdsSettings& dds);
QosPtr plots_writer_qos(const DdsSettings& dds);
// Tracks: reliable, keyed by sensor, durability from the config (transient-local by default,
// so a late display gets the current picture of every sensor). Recorders keep all.
QosPtr tracks_writer_qos(const DdsSettings& dds);
QosPtr tracks_reader_qos(const DdsSettings& dds, bool keep_all);
// Status: reliable, transient-local, keep last 1, with the configured deadline.
QosPtr status_writer_qos(const DdsSettings& dds);
QosPtr status_reader_qos(const DdsSettings& dds);

class DdsSession {
 public:
  /// Checks the DDS configuration (ensure_dds_configuration), then creates the participant on
  /// the configured domain with a publisher and subscriber in the configured partitions.
  static Expected<DdsSession> open(const DdsSettings& dds);

  DdsSession(DdsSession&& other) noexcept;
  DdsSession& operator=(DdsSession&& other) noexcept;
  DdsSession(const DdsSession&) = delete;
  DdsSession& operator=(const DdsSession&) = delete;
  ~DdsSession();

  dds_entity_t participant() const { return participant_; }
  const std::string& configuration() const { return configuration_; }

  Expected<dds_entity_t> topic(const dds_topic_descriptor_t* descriptor, const std::string& name);
  Expected<dds_entity_t> reader(dds_entity_t topic, const dds_qos_t* qos);
  Expected<dds_entity_t> writer(dds_entity_t topic, const dds_qos_t* qos);

 private:
  DdsSession() = default;
  dds_entity_t participant_ = 0;
  dds_entity_t publisher_ = 0;
  dds_entity_t subscriber_ = 0;
  std::string configuration_;
};

/// Waits until `writer` has matched at least `count` readers (or `reader` has matched `count`
/// writers), polling `keep_waiting` every 100 ms; false on timeout or when told to stop.
bool wait_for_readers(dds_entity_t writer, std::uint32_t count, std::chrono::milliseconds timeout,
                      const std::function<bool()>& keep_waiting = {});
bool wait_for_writers(dds_entity_t reader, std::uint32_t count, std::chrono::milliseconds timeout,
                      const std::function<bool()>& keep_waiting = {});

}  // namespace skytrack::daemon
