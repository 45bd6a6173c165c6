// Fuzz target: any bytes as one ground-truth line (docs/formats.md) through
// skytrack::io::parse_truth_frame. Besides not crashing (ASan, UBSan), an accepted line must
// hold what the format promises (2 or 3 dims, finite values, members not negative) and
// survive the writer: to_json then parse gives back the same frame.
#include <cmath>
#include <string_view>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/jsonl_writer.hpp"

int skytrack_truth_line_fuzz_one(const std::uint8_t* data, std::size_t size) {
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  const auto parsed = skytrack::io::parse_truth_frame(line);
  if (!parsed) return 0;
  SKYTRACK_FUZZ_CHECK(std::isfinite(parsed->time));
  for (const skytrack::TruthObject& o : parsed->objects) {
    SKYTRACK_FUZZ_CHECK(o.dims == 2 || o.dims == 3);
    SKYTRACK_FUZZ_CHECK(o.position.allFinite() && o.velocity.allFinite());
    SKYTRACK_FUZZ_CHECK(!o.extent || o.extent->allFinite());
    SKYTRACK_FUZZ_CHECK(!o.members || *o.members >= 0);
  }
  const auto again = skytrack::io::parse_truth_frame(skytrack::io::to_json(*parsed));
  SKYTRACK_FUZZ_CHECK(again.has_value());
  SKYTRACK_FUZZ_CHECK(*again == *parsed);
  return 0;
}
