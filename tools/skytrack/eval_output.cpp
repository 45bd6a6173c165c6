#include "eval_output.hpp"

#include <cmath>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace skytrack::tool {
namespace {

/// A JSON number, or null for NaN / inf (JSON has neither). fmt's {} is the shortest
/// representation that reads back bit-identical.
std::string json_number(double v) {
  return std::isfinite(v) ? fmt::format("{}", v) : "null";
}

}  // namespace

bool PerScanWriter::open(const std::string& path) {
  if (path.empty()) return true;
  file_ = std::fopen(path.c_str(), "w");
  if (file_ == nullptr) return false;
  jsonl_ = path.size() >= 6 && path.compare(path.size() - 6, 6, ".jsonl") == 0;
  if (!jsonl_) {
    fmt::print(file_,
               "time,ospa,gospa,gospa_localisation,gospa_missed,gospa_false,truths,"
               "tracks\n");
  }
  return true;
}

void PerScanWriter::write(const metrics::ScanRecord& r) {
  if (file_ == nullptr) return;
  if (jsonl_) {
    fmt::print(file_,
               "{{\"time\": {}, \"ospa\": {}, \"gospa\": {}, \"gospa_localisation\": {}, "
               "\"gospa_missed\": {}, \"gospa_false\": {}, \"truths\": {}, \"tracks\": {}}}\n",
               json_number(r.time), json_number(r.ospa), json_number(r.gospa),
               json_number(r.gospa_localisation), r.gospa_missed, r.gospa_false, r.truths,
               r.tracks);
  } else {
    fmt::print(file_, "{},{},{},{},{},{},{},{}\n", r.time, r.ospa, r.gospa, r.gospa_localisation,
               r.gospa_missed, r.gospa_false, r.truths, r.tracks);
  }
}

bool PerScanWriter::close() {
  if (file_ == nullptr) return true;
  const bool ok = std::ferror(file_) == 0;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  return ok && closed;
}

std::string summary_json(const metrics::EvaluationSummary& s, double cutoff, double order,
                         const RunCounts& c) {
  std::string json = fmt::format(
      "{{\"gospa_mean\": {}, \"ospa_mean\": {}, \"gospa_localisation_mean\": {}, "
      "\"gospa_missed_mean\": {}, \"gospa_false_mean\": {}, \"rmse_position\": {}, "
      "\"rmse_velocity\": {}, \"matched_pairs\": {}, \"id_changes\": {}, "
      "\"fragmentations\": {}, \"kept_id_changes\": {}, \"kept_fragmentations\": {}, "
      "\"gwd_mean\": {}, \"gwd_pairs\": {}, \"scans\": {}, "
      "\"cutoff\": {}, \"order\": {}, \"truth_lines_rejected\": {}, "
      "\"track_lines_rejected\": {}, \"track_frames\": {}, \"track_frames_without_truth\": {}, "
      "\"continuity\": [",
      json_number(s.gospa_mean), json_number(s.ospa_mean), json_number(s.gospa_localisation_mean),
      json_number(s.gospa_missed_mean), json_number(s.gospa_false_mean),
      json_number(s.rmse_position), json_number(s.rmse_velocity), s.matched_pairs, s.id_changes,
      s.fragmentations, s.kept_id_changes, s.kept_fragmentations, json_number(s.gwd_mean),
      s.gwd_pairs, s.scans, json_number(cutoff), json_number(order), c.truth_rejected,
      c.track_rejected, c.track_frames, c.track_frames_without_truth);
  for (std::size_t i = 0; i < s.continuity.size(); ++i) {
    const metrics::TruthContinuity& t = s.continuity[i];
    json += fmt::format(
        "{}{{\"truth\": {}, \"frames_present\": {}, \"frames_tracked\": {}, "
        "\"id_changes\": {}, \"fragmentations\": {}, \"distinct_tracks\": {}, "
        "\"tracks\": [{}]}}",
        i == 0 ? "" : ", ", t.truth_id, t.frames_present, t.frames_tracked, t.id_changes,
        t.fragmentations, t.distinct_tracks, fmt::join(t.tracks, ", "));
  }
  return json + "]}";
}

void print_table(const metrics::EvaluationSummary& s, double cutoff, double order,
                 const RunCounts& c) {
  const auto num = [](double v, std::string_view unit) {
    return std::isfinite(v) ? fmt::format("{:.3f} {}", v, unit) : std::string("n/a");
  };
  fmt::print("skytrack eval: {} scans, cutoff c = {} m, order p = {}\n", s.scans, cutoff, order);
  fmt::print("  {:<26}{}\n", "GOSPA mean", num(s.gospa_mean, "m"));
  fmt::print("  {:<26}{}\n", "  localisation mean",
             num(s.gospa_localisation_mean, fmt::format("m^{}", order)));
  fmt::print("  {:<26}{:.3f} per scan\n", "  missed truths mean", s.gospa_missed_mean);
  fmt::print("  {:<26}{:.3f} per scan\n", "  false tracks mean", s.gospa_false_mean);
  fmt::print("  {:<26}{}\n", "OSPA mean", num(s.ospa_mean, "m"));
  fmt::print("  {:<26}{} over {} matched pairs\n", "RMSE position", num(s.rmse_position, "m"),
             s.matched_pairs);
  fmt::print("  {:<26}{}\n", "RMSE velocity", num(s.rmse_velocity, "m/s"));
  fmt::print("  {:<26}{} over {} pairs with extents\n", "GWD mean", num(s.gwd_mean, "m"),
             s.gwd_pairs);
  fmt::print("  {:<26}{}\n", "id changes", s.id_changes);
  fmt::print("  {:<26}{}\n", "fragmentations", s.fragmentations);
  fmt::print("  {:<26}{} (fragmentations {})\n", "id changes, kept (MOT)", s.kept_id_changes,
             s.kept_fragmentations);
  fmt::print("  {:<26}truth {}, tracks {}\n", "rejected lines", c.truth_rejected, c.track_rejected);
  if (s.continuity.empty() || s.continuity.size() > 50) return;
  fmt::print("\n  {:>8} {:>9} {:>9} {:>11} {:>15} {:>7}\n", "truth", "present", "tracked",
             "id changes", "fragmentations", "tracks");
  for (const metrics::TruthContinuity& t : s.continuity) {
    fmt::print("  {:>8} {:>9} {:>9} {:>11} {:>15} {:>7}\n", t.truth_id, t.frames_present,
               t.frames_tracked, t.id_changes, t.fragmentations, t.distinct_tracks);
  }
}

}  // namespace skytrack::tool
