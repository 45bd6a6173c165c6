#pragma once
// skytrackd in the fusion role: the local trackers' TrackBatch in (keyed by sensor), the same
// fusion object as `skytrack fuse`, the fused TrackBatch and TrackerStatus out. One thread of
// its own takes, fuses and publishes; the owner's thread publishes the status and stops it.
// docs/fusion.md ("Deployment") describes the setup.
#include <memory>

#include "skytrack/core/expected.hpp"
#include "skytrack/daemon/daemon_config.hpp"
#include "skytrack/fusion/fusion_spec.hpp"

namespace skytrack::daemon {

class FusionNode {
 public:
  /// Opens DDS and creates the topics, the reader and the writers for `spec` (the fusion file
  /// the configuration names, already loaded). Nothing runs yet.
  static Expected<std::unique_ptr<FusionNode>> create(const DaemonConfig& config,
                                                      const fusion::FusionSpec& spec);
  ~FusionNode();  // stops if still running, then deletes the DDS participant
  FusionNode(const FusionNode&) = delete;
  FusionNode& operator=(const FusionNode&) = delete;

  void start();
  void publish_status();
  /// Stops reception, fuses the cycles still open and publishes them, then a final status.
  void stop();

 private:
  struct Impl;
  explicit FusionNode(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace skytrack::daemon
