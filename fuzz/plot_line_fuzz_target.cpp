// Fuzz target: any bytes as one plot-stream line (docs/formats.md) through
// skytrack::io::parse_plot_scan. Besides not crashing (ASan, UBSan), an accepted line must
// hold what the format promises (finite values, one form per plot, positive sigmas, unique
// ids, transponder codes in range) and survive the writer: to_json then parse gives back the
// same scan, with no plot dropped (the writers' bit-exact round trip).
#include <cmath>
#include <optional>
#include <string_view>
#include <unordered_set>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace {

using skytrack::MeasurementSigma;
using skytrack::Plot;
using skytrack::PlotForm;
using skytrack::PlotScan;

bool finite_or_absent(const std::optional<double>& value) {
  return !value || std::isfinite(*value);
}

bool positive_or_absent(const std::optional<double>& value) {
  return !value || (std::isfinite(*value) && *value > 0.0);
}

void check_sigma(const MeasurementSigma& s) {
  SKYTRACK_FUZZ_CHECK(positive_or_absent(s.range) && positive_or_absent(s.azimuth) &&
                      positive_or_absent(s.elevation) && positive_or_absent(s.range_rate) &&
                      positive_or_absent(s.x) && positive_or_absent(s.y) &&
                      positive_or_absent(s.z));
}

void check_plot(const Plot& p) {
  if (p.form == PlotForm::kPolar) {
    SKYTRACK_FUZZ_CHECK(std::isfinite(p.range) && p.range >= 0.0 && std::isfinite(p.azimuth));
    SKYTRACK_FUZZ_CHECK(finite_or_absent(p.elevation) && finite_or_absent(p.range_rate));
  } else {
    SKYTRACK_FUZZ_CHECK(std::isfinite(p.x) && std::isfinite(p.y) && finite_or_absent(p.z));
  }
  SKYTRACK_FUZZ_CHECK(finite_or_absent(p.time) && finite_or_absent(p.snr_db) &&
                      finite_or_absent(p.amplitude));
  SKYTRACK_FUZZ_CHECK(!p.mode3a || *p.mode3a <= 07777);
  SKYTRACK_FUZZ_CHECK(!p.mode_s || *p.mode_s <= 0xFFFFFFu);
  SKYTRACK_FUZZ_CHECK(!p.flight_level || (*p.flight_level >= -15.0 && *p.flight_level <= 1500.0));
  check_sigma(p.sigma);
}

void check_scan(const PlotScan& scan) {
  SKYTRACK_FUZZ_CHECK(std::isfinite(scan.time));
  SKYTRACK_FUZZ_CHECK(scan.platform.position.allFinite() && scan.platform.velocity.allFinite() &&
                      scan.platform.attitude.allFinite());
  SKYTRACK_FUZZ_CHECK(!scan.coverage ||
                      (std::isfinite(scan.coverage->from) && std::isfinite(scan.coverage->to)));
  check_sigma(scan.sigma);
  std::unordered_set<std::int64_t> ids;
  for (const Plot& p : scan.plots) {
    check_plot(p);
    SKYTRACK_FUZZ_CHECK(ids.insert(p.id).second);
  }
}

}  // namespace

int skytrack_plot_line_fuzz_one(const std::uint8_t* data, std::size_t size) {
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  const auto parsed = skytrack::io::parse_plot_scan(line);
  if (!parsed) return 0;
  check_scan(parsed->scan);
  const std::string written = skytrack::io::to_json(parsed->scan);
  const auto again = skytrack::io::parse_plot_scan(written);
  SKYTRACK_FUZZ_CHECK(again.has_value());
  SKYTRACK_FUZZ_CHECK(again->rejected_plots.empty());
  SKYTRACK_FUZZ_CHECK(again->scan == parsed->scan);
  return 0;
}
