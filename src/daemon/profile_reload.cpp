// The daemon's profile: the one it starts with, and what a SIGHUP's new profile changes (the
// decision to keep or restart the tracks, docs/daemon.md).
#include <string>

#include "skytrack/config/profile_loader.hpp"
#include "skytrack/daemon/daemon.hpp"

namespace skytrack::daemon {

Expected<config::TrackingProfile> load_tracking_profile(const std::string& path) {
  if (path.empty()) {
    config::TrackingProfile profile;
    profile.identity = {"default", "1", "built-in default point-tracking profile"};
    return profile;
  }
  return config::load_profile(path);
}

std::string restart_reason(const config::TrackingProfile& a, const config::TrackingProfile& b) {
  // The decision compares the whole profile, so a section added later cannot be forgotten;
  // only the identity and the input limits (which the running pipeline takes) are left out.
  const auto tracking = [](config::TrackingProfile p) {
    p.identity = {};
    p.input_limits = {};
    return p;
  };
  if (tracking(a) == tracking(b)) return {};
  std::string out;
  const auto differs = [&out](bool same, const char* section) {
    if (!same) out += (out.empty() ? "" : ", ") + std::string(section);
  };
  differs(a.mode == b.mode, "mode");
  differs(a.dimension == b.dimension, "dimension");
  differs(a.measurement == b.measurement, "measurement");
  differs(a.antenna == b.antenna, "antenna");
  differs(a.motion_models == b.motion_models, "motion_models");
  differs(a.mode_transition == b.mode_transition, "mode_transition");
  differs(a.mode_transition_interval == b.mode_transition_interval, "mode_transition_interval");
  differs(a.initial_mode_probabilities == b.initial_mode_probabilities,
          "initial_mode_probabilities");
  differs(a.association == b.association, "association");
  differs(a.clutter_rejection == b.clutter_rejection, "clutter_rejection");
  differs(a.point.initiation == b.point.initiation, "point.initiation");
  differs(a.point.track_life == b.point.track_life, "point.track_life");
  differs(a.point.branching == b.point.branching, "point.branching");
  differs(a.bernoulli == b.bernoulli, "bernoulli");
  differs(a.group == b.group, "group");
  differs(a.extended == b.extended, "extended");
  return out.empty() ? "tracking parameters" : out;
}

}  // namespace skytrack::daemon
