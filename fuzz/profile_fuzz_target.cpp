// Fuzz target: any bytes as a tracking profile's YAML through skytrack::config::parse_profile.
// A profile the loader accepts (what `skytrack check-profile` passes) and Pipeline::create
// takes then tracks two short streams, one 2-D and Cartesian, one 3-D and polar (the
// dimension is chosen by the first batch), so that a number the loader lets through but the
// tracker cannot live with (a tiny cell, a huge sigma) shows up under ASan and UBSan.
#include <string>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "skytrack/config/profile_loader.hpp"
#include "skytrack/pipeline/pipeline.hpp"

namespace {

using skytrack::Plot;
using skytrack::PlotForm;
using skytrack::PlotScan;

Plot cartesian(std::int64_t id, double x, double y) {
  Plot p;
  p.id = id;
  p.form = PlotForm::kCartesian;
  p.x = x;
  p.y = y;
  return p;
}

Plot polar(std::int64_t id, double range, double azimuth, double elevation) {
  Plot p;
  p.id = id;
  p.range = range;
  p.azimuth = azimuth;
  p.elevation = elevation;
  p.flight_level = 100.0;
  return p;
}

/// Two targets 4 s apart per batch, and a stray plot: enough for initiation, gating,
/// association and confirmation to run.
void track_streams(const skytrack::config::TrackingProfile& profile) {
  for (int stream = 0; stream < 2; ++stream) {
    auto pipeline = skytrack::Pipeline::create(profile);
    if (!pipeline) return;
    for (int k = 0; k < 4; ++k) {
      PlotScan scan;
      scan.sensor = 1;
      scan.scan = static_cast<std::uint64_t>(k);
      scan.time = 4.0 * k;
      const double step = 4.0 * k;
      if (stream == 0) {
        scan.plots = {cartesian(0, 10000.0 + 200.0 * step, 5000.0),
                      cartesian(1, -20000.0, 8000.0 - 150.0 * step),
                      cartesian(2, 3000.0 * k, -4000.0 * k)};
      } else {
        scan.plots = {polar(0, 30000.0 + 250.0 * step, 0.5, 0.05),
                      polar(1, 45000.0, 2.0 + 0.004 * step, 0.02),
                      polar(2, 12000.0 + 900.0 * k, -1.0 * k, 0.1)};
      }
      pipeline->process(scan);
    }
  }
}

}  // namespace

int skytrack_profile_fuzz_one(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto profile = skytrack::config::parse_profile(text, "fuzz.yaml");
  if (!profile) {
    SKYTRACK_FUZZ_CHECK(!profile.error().message.empty());
    return 0;
  }
  track_streams(*profile);
  return 0;
}
