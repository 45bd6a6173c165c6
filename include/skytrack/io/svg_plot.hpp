#pragma once
// SVG picture of an evaluation run: left, truth trajectories against the scored
// (confirmed / coasting) track positions, x east / y north at equal scale; right, GOSPA
// over time with its split. Pure string building from plain data: the caller writes it.
#include <cstdint>
#include <string>
#include <vector>

namespace skytrack::io {

/// One trajectory [m]; points in time order.
struct PlotSeries {
  std::int64_t id = 0;
  std::vector<double> x;  // east
  std::vector<double> y;  // north
};

/// GOSPA per scan with its split in the p-th power domain, where
///   gospa^p = localisation + c^p/2 (missed + false).
struct GospaTimeline {
  std::vector<double> time;          // [s]
  std::vector<double> gospa;         // [m]
  std::vector<double> localisation;  // sum of d^p over matched pairs [m^p]
  std::vector<double> missed;        // number of missed truths
  std::vector<double> false_tracks;  // number of false tracks
};

struct EvaluationPlot {
  std::string title;
  std::string subtitle;  // e.g. a one-line summary
  std::vector<PlotSeries> truths;
  std::vector<PlotSeries> tracks;
  GospaTimeline gospa;
  double cutoff = 100.0;  // c [m]
  double order = 2.0;     // p
};

/// A complete standalone SVG document. The GOSPA split is drawn as stacked areas of each
/// term's share of gospa^p scaled to gospa, so the stack's top is the GOSPA curve.
std::string render_evaluation_svg(const EvaluationPlot& plot);

}  // namespace skytrack::io
