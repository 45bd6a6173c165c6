// `skytrack eval`: scores a track file against a truth file (CONTRACTS.md §2, §3) with
// OSPA / GOSPA, RMSE, track continuity and GWD (metrics/scenario_evaluation.hpp). Both
// files are streamed in time order; track frames are matched to truth frames by time.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands.hpp"
#include "eval_identity.hpp"
#include "eval_output.hpp"
#include "skytrack/io/jsonl_reader.hpp"
#include "skytrack/io/svg_plot.hpp"
#include "skytrack/metrics/scenario_evaluation.hpp"
#include "track_frame_matcher.hpp"

namespace skytrack::tool {
namespace {

constexpr std::size_t kMaxErrorsShown = 20;   // per file, then only counted
constexpr std::size_t kMaxPlotPoints = 4000;  // per series, by adaptive decimation

struct EvalOptions {
  std::string truth_path, tracks_path, plot_path, per_scan_path;
  double cutoff = metrics::ScenarioEvaluationConfig{}.cutoff;
  double order = metrics::ScenarioEvaluationConfig{}.order;
  bool json = false;
  bool hold = false;
};

/// Error sink that prints the first few rejected lines of a file and counts the rest.
io::ErrorSink printing_sink(std::size_t& shown) {
  return [&shown](const io::LineError& error) {
    if (shown < kMaxErrorsShown) {
      fmt::print(stderr, "{}\n", io::to_string(error));
    } else if (shown == kMaxErrorsShown) {
      fmt::print(stderr, "{}: further rejected lines are counted, not shown\n", error.file);
    }
    ++shown;
  };
}

/// Keeps every stride-th point; halves the kept points and doubles the stride when full, so
/// a long run keeps an even spread of at most kMaxPlotPoints.
template <class Point>
struct Decimated {
  std::vector<Point> points;
  std::size_t seen = 0, stride = 1;
  void add(const Point& p) {
    if (seen++ % stride != 0) return;
    if (points.size() == kMaxPlotPoints) {
      for (std::size_t i = 0; i < points.size() / 2; ++i) points[i] = points[2 * i];
      points.resize(points.size() / 2);
      stride *= 2;
      if ((seen - 1) % stride != 0) return;
    }
    points.push_back(p);
  }
};

struct XY {
  double x, y;
};
struct GospaPoint {
  double time, gospa, localisation, missed, false_tracks;
};

struct PlotCollector {
  std::map<std::int64_t, Decimated<XY>> truths, tracks;
  Decimated<GospaPoint> gospa;

  void add(const TruthFrame& truth, const TrackFrame* tracks_now,
           const metrics::ScanRecord& record) {
    for (const TruthObject& o : truth.objects) truths[o.id].add({o.position.x(), o.position.y()});
    if (tracks_now != nullptr) {
      for (const TrackReport& t : tracks_now->tracks) {
        if (is_reported_as_firm(t.status)) tracks[t.id].add({t.position.x(), t.position.y()});
      }
    }
    gospa.add({record.time, record.gospa, record.gospa_localisation,
               static_cast<double>(record.gospa_missed), static_cast<double>(record.gospa_false)});
  }

  static std::vector<io::PlotSeries> series(const std::map<std::int64_t, Decimated<XY>>& in) {
    std::vector<io::PlotSeries> out;
    for (const auto& [id, d] : in) {
      io::PlotSeries s{id, {}, {}};
      for (const XY& p : d.points) {
        s.x.push_back(p.x);
        s.y.push_back(p.y);
      }
      out.push_back(std::move(s));
    }
    return out;
  }

  io::EvaluationPlot build(const EvalOptions& options, std::string subtitle) const {
    io::EvaluationPlot plot;
    const auto file_name = [](const std::string& path) {
      return path.substr(path.find_last_of('/') + 1);  // npos + 1 == 0
    };
    plot.title = fmt::format("skytrack eval: {} against {}", file_name(options.tracks_path),
                             file_name(options.truth_path));
    plot.subtitle = std::move(subtitle);
    plot.truths = series(truths);
    plot.tracks = series(tracks);
    plot.cutoff = options.cutoff;
    plot.order = options.order;
    for (const GospaPoint& p : gospa.points) {
      plot.gospa.time.push_back(p.time);
      plot.gospa.gospa.push_back(p.gospa);
      plot.gospa.localisation.push_back(p.localisation);
      plot.gospa.missed.push_back(p.missed);
      plot.gospa.false_tracks.push_back(p.false_tracks);
    }
    return plot;
  }
};

bool write_text_file(const std::string& path, const std::string& text) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (file == nullptr) return false;
  const bool ok = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  return std::fclose(file) == 0 && ok;
}

/// Prints the summary and writes the plot; false if the plot cannot be written.
bool report(const metrics::EvaluationSummary& summary, const EvalOptions& options,
            const RunCounts& counts, const std::optional<PlotCollector>& plot) {
  if (options.json) {
    fmt::print("{}\n", summary_json(summary, options.cutoff, options.order, counts));
  } else {
    print_table(summary, options.cutoff, options.order, counts);
  }
  if (!plot) return true;
  const auto num = [](double v) {
    return std::isfinite(v) ? fmt::format("{:.1f} m", v) : std::string("n/a");
  };
  const std::string subtitle = fmt::format(
      "{} scans | GOSPA mean {} | OSPA mean {} | RMSE position {} | id changes {} | "
      "fragmentations {}",
      summary.scans, num(summary.gospa_mean), num(summary.ospa_mean), num(summary.rmse_position),
      summary.id_changes, summary.fragmentations);
  if (!write_text_file(options.plot_path,
                       io::render_evaluation_svg(plot->build(options, subtitle)))) {
    fmt::print(stderr, "skytrack eval: cannot write {}\n", options.plot_path);
    return false;
  }
  return true;
}

/// A truth file given as tracks: each object becomes a confirmed track with the object's id,
/// so `eval --truth T --tracks T` checks the chain and scores 0.
TrackFrame tracks_from_truth(const TruthFrame& truth) {
  TrackFrame frame;
  frame.time = truth.time;
  for (const TruthObject& object : truth.objects) {
    TrackReport track;
    track.id = object.id;
    track.status = TrackStatus::kConfirmed;
    track.kind = object.kind;
    track.dims = object.dims;
    track.position = object.position;
    track.velocity = object.velocity;
    track.extent = object.extent;
    track.members = object.members;
    frame.tracks.push_back(std::move(track));
  }
  return frame;
}

/// True when the file's first non-blank line is a truth frame rather than a track frame.
bool holds_truth(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    return !io::parse_track_frame(line) && io::parse_truth_frame(line).has_value();
  }
  return false;
}

int run_eval(const EvalOptions& options) {
  RunCounts counts;
  std::size_t truth_shown = 0, track_shown = 0;
  auto truth_reader = io::TruthReader::open(options.truth_path, printing_sink(truth_shown));
  if (!truth_reader) {
    fmt::print(stderr, "skytrack eval: {}\n", truth_reader.error().message);
    return 2;
  }
  // --tracks may name a track file or, to check the evaluation chain, a truth file.
  std::optional<io::TrackReader> track_reader;
  std::optional<io::TruthReader> truth_as_tracks;
  TrackFrameMatcher::Source source;
  if (holds_truth(options.tracks_path)) {
    auto reader = io::TruthReader::open(options.tracks_path, printing_sink(track_shown));
    if (!reader) {
      fmt::print(stderr, "skytrack eval: {}\n", reader.error().message);
      return 2;
    }
    truth_as_tracks.emplace(std::move(*reader));
    source = [&]() -> std::optional<TrackFrame> {
      auto truth = truth_as_tracks->next();
      if (!truth) return std::nullopt;
      return tracks_from_truth(*truth);
    };
  } else {
    auto reader = io::TrackReader::open(options.tracks_path, printing_sink(track_shown));
    if (!reader) {
      fmt::print(stderr, "skytrack eval: {}\n", reader.error().message);
      return 2;
    }
    track_reader.emplace(std::move(*reader));
    source = [&] { return track_reader->next(); };
  }
  PerScanWriter per_scan;
  if (!per_scan.open(options.per_scan_path)) {
    fmt::print(stderr, "skytrack eval: cannot write {}\n", options.per_scan_path);
    return 2;
  }

  metrics::ScenarioEvaluation evaluation({options.cutoff, options.order});
  std::optional<PlotCollector> plot;
  if (!options.plot_path.empty()) plot.emplace();

  TrackFrameMatcher matcher(source, counts, options.hold);
  while (std::optional<TruthFrame> truth = truth_reader->next()) {
    const TrackFrame* tracks = matcher.at(truth->time);
    const metrics::ScanRecord& record = evaluation.add(*truth, tracks);
    per_scan.write(record);
    if (plot) plot->add(*truth, tracks, record);
  }
  matcher.finish();
  for (const auto* error :
       {&truth_reader->read_error(), track_reader ? &track_reader->read_error() : nullptr,
        truth_as_tracks ? &truth_as_tracks->read_error() : nullptr}) {
    if (error != nullptr && *error) {
      fmt::print(stderr, "skytrack eval: {}\n", **error);
      return 2;
    }
  }

  counts.truth_rejected = truth_reader->counts().rejected_lines;
  counts.track_rejected = track_reader ? track_reader->counts().rejected_lines
                                       : truth_as_tracks->counts().rejected_lines;
  if (counts.track_frames_without_truth > 0) {
    fmt::print(stderr,
               "skytrack eval: {} of {} track frames have no truth frame at their time (first "
               "at t = {} s); they are not scored\n",
               counts.track_frames_without_truth, counts.track_frames, *counts.first_orphan_time);
  }
  int exit_code = 0;
  if (!per_scan.close()) {
    fmt::print(stderr, "skytrack eval: writing {} failed\n", options.per_scan_path);
    exit_code = 2;
  }

  if (!report(evaluation.summary(), options, counts, plot)) exit_code = 2;
  return exit_code;
}

}  // namespace

void add_eval_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<EvalOptions>();
  CLI::App* cmd = app.add_subcommand(
      "eval", "Score tracks against ground truth: OSPA/GOSPA, RMSE, track continuity, GWD");
  auto identity = std::make_shared<IdentityOptions>();
  auto by_identity = std::make_shared<bool>(false);
  cmd->add_option("--truth", options->truth_path, "Ground-truth JSON Lines file");
  cmd->add_option("--tracks", options->tracks_path, "Track-output JSON Lines file")->required();
  cmd->add_flag("--identity", *by_identity,
                "Score against the plots' transponder identities instead of a truth file "
                "(needs --plots)");
  cmd->add_option("--plots", identity->plots_path,
                  "--identity: the plot stream the tracks were made from");
  cmd->add_option("--gap", identity->gap,
                  "--identity: a silence longer than this ends an identity's segment [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--cutoff", options->cutoff, "OSPA/GOSPA cut-off c [m]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--order", options->order, "OSPA/GOSPA order p (1 to 20)")
      ->check(CLI::Range(1.0, 20.0))
      ->capture_default_str();
  cmd->add_flag("--json", options->json, "Print one JSON object instead of a table");
  cmd->add_flag("--hold", options->hold,
                "Score each truth time against the latest track frame at or before it, tracks "
                "moved on by their velocity (outputs of sector or block feeds)");
  cmd->add_option("--plot", options->plot_path, "Write an SVG picture of the run");
  cmd->add_option("--per-scan", options->per_scan_path,
                  "Write per-scan metrics (JSON Lines if it ends in .jsonl, else CSV)");
  cmd->footer(
      "Example: skytrack eval --truth out/default.truth.jsonl --tracks "
      "out/default.tracks.jsonl --cutoff 500 --plot out/default.svg\nExit codes: 0 "
      "scored; 2 an input cannot be read, a needed option is missing or an output "
      "cannot be written; 1xx command-line mistakes (CLI11: 105 a bad value, 106 a "
      "required option missing, 109 an unknown argument).");
  cmd->callback([options, identity, by_identity, &exit_code] {
    if (*by_identity) {
      if (identity->plots_path.empty()) {
        fmt::print(stderr, "skytrack eval: --identity needs --plots\n");
        exit_code = 2;
        return;
      }
      identity->tracks_path = options->tracks_path;
      identity->json = options->json;
      exit_code = run_eval_identity(*identity);
      return;
    }
    if (options->truth_path.empty()) {
      fmt::print(stderr, "skytrack eval: --truth is required (or --identity --plots P)\n");
      exit_code = 2;
      return;
    }
    exit_code = run_eval(*options);
  });
}

}  // namespace skytrack::tool
