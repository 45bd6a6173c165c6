// Fuzz target: any bytes as one track-output line (docs/formats.md) through
// skytrack::io::parse_track_frame. Besides not crashing (ASan, UBSan), an accepted line must
// hold what the format promises (2 or 3 dims, a covariance of 0, 16 or 36 finite numbers,
// probabilities in [0, 1], finite values) and survive the writer: to_json then parse gives
// back the same frame (the writers' bit-exact round trip).
#include <cmath>
#include <string_view>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"

namespace {

void check_track(const skytrack::TrackReport& t) {
  SKYTRACK_FUZZ_CHECK(t.dims == 2 || t.dims == 3);
  SKYTRACK_FUZZ_CHECK(t.position.allFinite() && t.velocity.allFinite());
  SKYTRACK_FUZZ_CHECK(t.dims == 3 || (t.position.z() == 0.0 && t.velocity.z() == 0.0));
  const std::size_t n = t.covariance.size();
  SKYTRACK_FUZZ_CHECK(n == 0 || n == static_cast<std::size_t>(t.dims == 3 ? 36 : 16));
  for (const double c : t.covariance) SKYTRACK_FUZZ_CHECK(std::isfinite(c));
  for (const auto& [name, p] : t.modes) SKYTRACK_FUZZ_CHECK(p >= 0.0 && p <= 1.0);
  SKYTRACK_FUZZ_CHECK(!t.quality || std::isfinite(*t.quality));
  SKYTRACK_FUZZ_CHECK(!t.extent || t.extent->allFinite());
  SKYTRACK_FUZZ_CHECK(!t.members || *t.members >= 0);
}

}  // namespace

int skytrack_track_line_fuzz_one(const std::uint8_t* data, std::size_t size) {
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  const auto parsed = skytrack::io::parse_track_frame(line);
  if (!parsed) return 0;
  SKYTRACK_FUZZ_CHECK(std::isfinite(parsed->time));
  for (const auto& t : parsed->tracks) check_track(t);
  for (const auto& a : parsed->associations) {
    SKYTRACK_FUZZ_CHECK(a.probability >= 0.0 && a.probability <= 1.0);
  }
  const auto again = skytrack::io::parse_track_frame(skytrack::io::to_json(*parsed));
  SKYTRACK_FUZZ_CHECK(again.has_value());
  SKYTRACK_FUZZ_CHECK(*again == *parsed);
  return 0;
}
