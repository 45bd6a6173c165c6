#include "frame_comparison.hpp"

#include <limits>

#include <fmt/format.h>

#include "skytrack/dds/conversion.hpp"
#include "skytrack/pipeline/pipeline.hpp"

namespace skytrack::adversary {
namespace {

/// The firm tracks of `frame` outside the flooded sector; counts those inside in `inside`.
std::vector<const TrackReport*> firm_outside(const TrackFrame& frame,
                                             const AdversaryGeometry& geometry,
                                             std::size_t* inside) {
  std::vector<const TrackReport*> out;
  for (const TrackReport& t : frame.tracks) {
    if (!is_reported_as_firm(t.status)) continue;
    if (geometry.contains(t.position, kSectorMargin)) {
      if (inside != nullptr) ++*inside;
      continue;
    }
    out.push_back(&t);
  }
  return out;
}

std::string where(const TrackReport& t) {
  return fmt::format("#{} {} at ({:.3f}, {:.3f}) km", t.id, to_string(t.status),
                     t.position.x() / 1e3, t.position.y() / 1e3);
}

}  // namespace

Expected<std::vector<std::optional<TrackFrame>>> offline_frames(
    const config::TrackingProfile& profile, const std::vector<PlotScan>& scans) {
  auto pipeline = Pipeline::create(profile);
  if (!pipeline) return unexpected(pipeline.error());
  std::vector<std::optional<TrackFrame>> frames;
  frames.reserve(scans.size());
  dds::PlotBatchSample sample;
  PlotScan received;
  for (const PlotScan& scan : scans) {
    if (auto ok = dds::to_dds(scan, sample); !ok) return unexpected(ok.error());
    if (auto ok = dds::from_dds(sample.get(), received); !ok) return unexpected(ok.error());
    const ScanResult& result = pipeline->process(received);
    frames.push_back(result.accepted ? std::optional<TrackFrame>(result.frame) : std::nullopt);
  }
  return frames;
}

FrameVerdict compare_frames(const TrackFrame* live, const std::optional<TrackFrame>& offline,
                            const AdversaryGeometry& geometry, double tolerance) {
  FrameVerdict v;
  if (live == nullptr || !offline) {
    v.unchanged = live == nullptr && !offline;
    if (!v.unchanged) {
      v.difference = live == nullptr ? "no TrackBatch received" : "offline run skipped the batch";
    }
    return v;
  }
  const auto want = firm_outside(*offline, geometry, nullptr);
  auto have = firm_outside(*live, geometry, &v.adversary);
  v.firm = want.size();
  for (const TrackReport* w : want) {
    double best = std::numeric_limits<double>::infinity();
    std::size_t at = have.size();
    for (std::size_t k = 0; k < have.size(); ++k) {
      if (have[k] == nullptr) continue;
      const double d = (have[k]->position - w->position).norm();
      if (d < best) {
        best = d;
        at = k;
      }
    }
    if (at == have.size() || best > tolerance) {
      if (v.difference.empty()) {
        v.difference = at == have.size()
                           ? fmt::format("offline track {} has no live counterpart", where(*w))
                           : fmt::format("offline track {}: nearest live track {} is {:.3g} m away",
                                         where(*w), where(*have[at]), best);
      }
      continue;
    }
    if (have[at]->status != w->status && v.difference.empty()) {
      v.difference =
          fmt::format("offline track {} is {} live", where(*w), to_string(have[at]->status));
    }
    v.numbers_differ = v.numbers_differ || have[at]->id != w->id;
    v.max_deviation = std::max(v.max_deviation, best);
    have[at] = nullptr;
  }
  for (const TrackReport* h : have) {
    if (h != nullptr && v.difference.empty()) {
      v.difference = fmt::format("live track {} is not in the offline run", where(*h));
    }
  }
  v.unchanged = v.difference.empty();
  return v;
}

}  // namespace skytrack::adversary
