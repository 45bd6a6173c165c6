#pragma once
// The fuzz targets beside the ASTERIX one (asterix_fuzz_target.cpp): each takes any bytes,
// returns 0 and aborts when an input breaks one of its invariants (ASan and UBSan catch the
// rest under libFuzzer). fuzz_main.cpp makes each a libFuzzer binary (-DSKYTRACK_FUZZ=ON,
// clang); tests/fuzz/fuzz_corpus_test.cpp runs each over its seed corpus, fuzz/seeds/<name>/,
// in the regular suite.
#include <cstddef>
#include <cstdint>

// One plot-stream line (docs/formats.md) through skytrack::io::parse_plot_scan.
int skytrack_plot_line_fuzz_one(const std::uint8_t* data, std::size_t size);
// One track-output line through parse_track_frame.
int skytrack_track_line_fuzz_one(const std::uint8_t* data, std::size_t size);
// One ground-truth line through parse_truth_frame.
int skytrack_truth_line_fuzz_one(const std::uint8_t* data, std::size_t size);
// A tracking profile's YAML through config::parse_profile, then a pipeline over two streams.
int skytrack_profile_fuzz_one(const std::uint8_t* data, std::size_t size);
// A scenario's YAML through config::parse_scenario.
int skytrack_scenario_fuzz_one(const std::uint8_t* data, std::size_t size);
// DDS PlotBatch samples built from the bytes, through dds::from_dds and Pipeline::process.
int skytrack_plot_batch_fuzz_one(const std::uint8_t* data, std::size_t size);
