// SVG rendering of an evaluation run (see svg_plot.hpp).
#include "skytrack/io/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string_view>

#include <fmt/format.h>

namespace skytrack::io {
namespace {

constexpr double kWidth = 1500.0, kHeight = 800.0;
constexpr double kPanelTop = 110.0, kPanelSize = 600.0;
constexpr double kLegendY = kPanelTop + kPanelSize + 78.0;  // below the x-axis label
constexpr double kMapLeft = 95.0;                           // map panel, square
constexpr double kTimeLeft = 820.0, kTimeWidth = 640.0;     // GOSPA panel
constexpr std::size_t kMinLabelledPoints = 5, kMaxTrackLabels = 20;
// Tableau 10: distinguishable on white, also for most colour-blind readers.
constexpr std::string_view kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                         "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
constexpr std::string_view kTruthColour = "#222222";
constexpr std::string_view kLocColour = "#6baed6", kMissColour = "#fd8d3c",
                           kFalseColour = "#e34a6f";

std::string escape(std::string_view text) {
  std::string out;
  for (const char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

/// Maps data to pixels on one axis.
struct Scale {
  double lo = 0.0, hi = 1.0;    // data
  double p0 = 0.0, p1 = 100.0;  // pixels (p1 < p0 for the upward y axis)
  double operator()(double v) const { return p0 + (v - lo) / (hi - lo) * (p1 - p0); }
};

/// "Nice" tick positions (1, 2, 5 x 10^k) covering [lo, hi] with about `count` ticks.
std::vector<double> nice_ticks(double lo, double hi, int count) {
  const double raw = (hi - lo) / std::max(1, count);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * magnitude;
    if (step >= raw) break;
  }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step) {
    ticks.push_back(std::abs(t) < 1e-9 * step ? 0.0 : t);
  }
  return ticks;
}

/// Tick label with as many decimals as the step needs.
std::string tick_label(double value, double step) {
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
  return fmt::format("{:.{}f}", value, decimals);
}

struct AxisSpec {
  Scale x, y;
  double x_unit = 1.0, y_unit = 1.0;  // data per label unit (1000 for km)
  std::string x_label, y_label;
};

void draw_axes(std::string& svg, const AxisSpec& a) {
  const double left = a.x.p0, right = a.x.p1, bottom = a.y.p0, top = a.y.p1;
  const auto xt = nice_ticks(a.x.lo, a.x.hi, 7);
  const auto yt = nice_ticks(a.y.lo, a.y.hi, 7);
  const double xs = xt.size() > 1 ? (xt[1] - xt[0]) / a.x_unit : 1.0;
  const double ys = yt.size() > 1 ? (yt[1] - yt[0]) / a.y_unit : 1.0;
  svg += "<g font-size=\"13\" fill=\"#333\">\n";
  for (const double t : xt) {
    const double px = a.x(t);
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#e4e4e4\"/>"
        "<line x1=\"{0:.1f}\" y1=\"{2:.1f}\" x2=\"{0:.1f}\" y2=\"{3:.1f}\" stroke=\"#333\"/>"
        "<text x=\"{0:.1f}\" y=\"{4:.1f}\" text-anchor=\"middle\">{5}</text>\n",
        px, top, bottom, bottom + 5, bottom + 20, tick_label(t / a.x_unit, xs));
  }
  for (const double t : yt) {
    const double py = a.y(t);
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{2:.1f}\" x2=\"{1:.1f}\" y2=\"{2:.1f}\" stroke=\"#e4e4e4\"/>"
        "<line x1=\"{3:.1f}\" y1=\"{2:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#333\"/>"
        "<text x=\"{4:.1f}\" y=\"{5:.1f}\" text-anchor=\"end\">{6}</text>\n",
        left, right, py, left - 5, left - 8, py + 4.5, tick_label(t / a.y_unit, ys));
  }
  svg += fmt::format(
      "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" "
      "stroke=\"#333\"/>\n",
      left, top, right - left, bottom - top);
  svg += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\" "
      "font-size=\"15\">{}</text>\n",
      0.5 * (left + right), bottom + 44, escape(a.x_label));
  svg += fmt::format(
      "<text transform=\"translate({:.1f},{:.1f}) rotate(-90)\" "
      "text-anchor=\"middle\" font-size=\"15\">{}</text>\n",
      left - 62, 0.5 * (top + bottom), escape(a.y_label));
  svg += "</g>\n";
}

std::string polyline(const std::vector<double>& xs, const std::vector<double>& ys, const Scale& sx,
                     const Scale& sy) {
  std::string points;
  const std::size_t n = std::min(xs.size(), ys.size());
  for (std::size_t i = 0; i < n; ++i) {
    fmt::format_to(std::back_inserter(points), "{:.1f},{:.1f} ", sx(xs[i]), sy(ys[i]));
  }
  return points;
}

/// Legend as one row of (swatch markup, label) items centred under a panel.
void draw_legend(std::string& svg, double centre_x, double y,
                 const std::vector<std::pair<std::string, std::string>>& items) {
  constexpr double kSwatch = 34.0, kGap = 22.0, kCharWidth = 6.8;  // ~13 px font
  double width = 0.0;
  for (const auto& item : items) {
    width += kSwatch + kCharWidth * static_cast<double>(item.second.size()) + kGap;
  }
  double x = centre_x - 0.5 * (width - kGap);
  for (const auto& [swatch, label] : items) {
    svg += fmt::format(
        "<g transform=\"translate({:.1f},{:.1f})\">{}</g>"
        "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"13\">{}</text>\n",
        x, y - 4.5, swatch, x + kSwatch, y, escape(label));
    x += kSwatch + kCharWidth * static_cast<double>(label.size()) + kGap;
  }
}

std::string colour_of(std::size_t index) {
  return std::string(kPalette[index % 10]);
}

/// A label beside a map point, flipped left near the right edge and kept inside the panel.
void map_label(std::string& svg, const AxisSpec& axes, double x, double y, double dy,
               const std::string& text, const std::string& colour, bool bold) {
  const double width = 7.5 * static_cast<double>(text.size());  // ~12 px font
  double px = axes.x(x) + 6.0;
  std::string_view anchor = "start";
  if (px + width > axes.x.p1) {
    px = axes.x(x) - 6.0;
    anchor = "end";
  }
  px = std::clamp(px, axes.x.p0 + 3.0, axes.x.p1 - 3.0);
  const double py = std::clamp(axes.y(y) + dy, axes.y.p1 + 14.0, axes.y.p0 - 4.0);
  svg += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"{}\" font-size=\"12\" "
      "font-weight=\"{}\" fill=\"{}\" stroke=\"white\" stroke-width=\"3\" "
      "paint-order=\"stroke\">{}</text>\n",
      px, py, anchor, bold ? "bold" : "normal", colour, escape(text));
}

/// Equal-scale axes: a square window around all points with a margin, km for large areas.
AxisSpec map_axes(const EvaluationPlot& plot) {
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo;
  for (const auto* set : {&plot.truths, &plot.tracks}) {
    for (const PlotSeries& s : *set) {
      for (const double v : s.x) {
        x_lo = std::min(x_lo, v);
        x_hi = std::max(x_hi, v);
      }
      for (const double v : s.y) {
        y_lo = std::min(y_lo, v);
        y_hi = std::max(y_hi, v);
      }
    }
  }
  if (!(x_lo <= x_hi && y_lo <= y_hi)) {  // nothing to draw: a 2 km window at the origin
    x_lo = y_lo = -1000.0;
    x_hi = y_hi = 1000.0;
  }
  const double span = std::max({x_hi - x_lo, y_hi - y_lo, 200.0}) * 1.1;
  const double cx = 0.5 * (x_lo + x_hi), cy = 0.5 * (y_lo + y_hi);
  AxisSpec axes;
  axes.x = {cx - span / 2, cx + span / 2, kMapLeft, kMapLeft + kPanelSize};
  axes.y = {cy - span / 2, cy + span / 2, kPanelTop + kPanelSize, kPanelTop};
  const bool km = span >= 5000.0;
  axes.x_unit = axes.y_unit = km ? 1000.0 : 1.0;
  axes.x_label = km ? "x east [km]" : "x east [m]";
  axes.y_label = km ? "y north [km]" : "y north [m]";
  return axes;
}

/// Truth as a wide grey band under the tracks and a thin dark line over them, so both stay
/// visible where a track sits on its truth; tracks as a thin line plus a dot per report.
void draw_map_series(std::string& svg, const EvaluationPlot& plot, const AxisSpec& axes) {
  std::vector<std::string> truth_points;
  for (const PlotSeries& s : plot.truths) {
    truth_points.push_back(polyline(s.x, s.y, axes.x, axes.y));
    svg += fmt::format(
        "<polyline fill=\"none\" stroke=\"#b8b8b8\" stroke-width=\"7\" "
        "stroke-linejoin=\"round\" stroke-linecap=\"round\" points=\"{}\"/>\n",
        truth_points.back());
  }
  for (std::size_t k = 0; k < plot.tracks.size(); ++k) {
    const PlotSeries& s = plot.tracks[k];
    svg += fmt::format(
        "<g fill=\"{0}\" stroke=\"none\"><polyline fill=\"none\" stroke=\"{0}\" "
        "stroke-width=\"1\" stroke-opacity=\"0.6\" points=\"{1}\"/>",
        colour_of(k), polyline(s.x, s.y, axes.x, axes.y));
    const std::size_t n = std::min(s.x.size(), s.y.size());
    for (std::size_t i = 0; i < n; ++i) {
      svg += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"2\"/>", axes.x(s.x[i]),
                         axes.y(s.y[i]));
    }
    svg += "</g>\n";
  }
  for (const std::string& points : truth_points) {
    svg += fmt::format(
        "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"1.2\" "
        "stroke-linejoin=\"round\" points=\"{}\"/>\n",
        kTruthColour, points);
  }
  for (const PlotSeries& s : plot.truths) {
    if (s.x.empty() || s.y.empty()) continue;
    svg += fmt::format(
        "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\" fill=\"white\" "
        "stroke=\"{}\" stroke-width=\"1.5\"/>\n",
        axes.x(s.x.front()), axes.y(s.y.front()), kTruthColour);
  }
}

/// Ids on top: the longest tracks at their end (short-lived false tracks would only clutter),
/// truths at their start.
void draw_map_labels(std::string& svg, const EvaluationPlot& plot, const AxisSpec& axes) {
  std::vector<std::size_t> labelled;
  for (std::size_t k = 0; k < plot.tracks.size(); ++k) {
    if (std::min(plot.tracks[k].x.size(), plot.tracks[k].y.size()) >= kMinLabelledPoints) {
      labelled.push_back(k);
    }
  }
  std::stable_sort(labelled.begin(), labelled.end(), [&](std::size_t a, std::size_t b) {
    return plot.tracks[a].x.size() > plot.tracks[b].x.size();
  });
  labelled.resize(std::min(labelled.size(), kMaxTrackLabels));
  for (const std::size_t k : labelled) {
    const PlotSeries& s = plot.tracks[k];
    map_label(svg, axes, s.x.back(), s.y.back(), 14.0, fmt::format("#{}", s.id), colour_of(k),
              false);
  }
  for (const PlotSeries& s : plot.truths) {
    if (s.x.empty() || s.y.empty()) continue;
    map_label(svg, axes, s.x.front(), s.y.front(), -6.0, fmt::format("T{}", s.id),
              std::string(kTruthColour), true);
  }
}

void draw_map(std::string& svg, const EvaluationPlot& plot) {
  const AxisSpec axes = map_axes(plot);
  draw_axes(svg, axes);
  svg += fmt::format(
      "<clipPath id=\"map\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/>"
      "</clipPath>\n<g clip-path=\"url(#map)\">\n",
      kMapLeft, kPanelTop, kPanelSize, kPanelSize);
  draw_map_series(svg, plot, axes);
  svg += "</g>\n";  // labels are not clipped but kept inside the panel by map_label
  draw_map_labels(svg, plot, axes);

  const std::string dots = fmt::format(
      "<circle cx=\"6\" cy=\"0\" r=\"2.5\" fill=\"{}\"/><circle cx=\"14\" cy=\"0\" "
      "r=\"2.5\" fill=\"{}\"/><circle cx=\"22\" cy=\"0\" r=\"2.5\" fill=\"{}\"/>",
      kPalette[0], kPalette[1], kPalette[2]);
  draw_legend(svg, kMapLeft + kPanelSize / 2, kLegendY,
              {{fmt::format("<line x1=\"0\" y1=\"0\" x2=\"28\" y2=\"0\" stroke=\"#b8b8b8\" "
                            "stroke-width=\"7\"/><line x1=\"0\" y1=\"0\" x2=\"28\" y2=\"0\" "
                            "stroke=\"{}\" stroke-width=\"1.2\"/>",
                            kTruthColour),
                fmt::format("truth ({} objects)", plot.truths.size())},
               {fmt::format("<circle cx=\"14\" cy=\"0\" r=\"4\" fill=\"white\" "
                            "stroke=\"{}\" stroke-width=\"1.5\"/>",
                            kTruthColour),
                "truth start, T<id>"},
               {dots, fmt::format("tracks, #<id> ({} ids)", plot.tracks.size())}});
}

void draw_gospa(std::string& svg, const EvaluationPlot& plot) {
  const GospaTimeline& g = plot.gospa;
  const std::size_t n = std::min({g.time.size(), g.gospa.size(), g.localisation.size(),
                                  g.missed.size(), g.false_tracks.size()});
  double t_lo = 0.0, t_hi = 1.0, top = 0.0;
  if (n > 0) {
    t_lo = g.time.front();
    t_hi = std::max(g.time[n - 1], t_lo + 1e-3);
    top = *std::max_element(g.gospa.begin(), g.gospa.begin() + static_cast<long>(n));
  }
  if (!(top > 0.0)) top = plot.cutoff;
  AxisSpec axes;
  axes.x = {t_lo, t_hi, kTimeLeft, kTimeLeft + kTimeWidth};
  axes.y = {0.0, top * 1.12, kPanelTop + kPanelSize, kPanelTop};
  axes.x_label = "time [s]";
  axes.y_label = "GOSPA [m]";
  draw_axes(svg, axes);

  // Share of each term in gospa^p, scaled to gospa, stacked: loc, then missed, then false.
  const double half_c_p = 0.5 * std::pow(plot.cutoff, plot.order);
  std::vector<double> lower(n, 0.0), upper(n, 0.0);
  const auto layer = [&](auto term, std::string_view colour) {
    for (std::size_t i = 0; i < n; ++i) {
      const double total_p = std::pow(g.gospa[i], plot.order);
      upper[i] = lower[i] + (total_p > 0.0 ? term(i) / total_p * g.gospa[i] : 0.0);
    }
    std::string points = polyline(g.time, upper, axes.x, axes.y);
    for (std::size_t i = n; i-- > 0;) {
      fmt::format_to(std::back_inserter(points), "{:.1f},{:.1f} ", axes.x(g.time[i]),
                     axes.y(lower[i]));
    }
    svg += fmt::format(
        "<polygon fill=\"{}\" fill-opacity=\"0.75\" stroke=\"none\" "
        "points=\"{}\"/>\n",
        colour, points);
    lower = upper;
  };
  layer([&](std::size_t i) { return g.localisation[i]; }, kLocColour);
  layer([&](std::size_t i) { return half_c_p * g.missed[i]; }, kMissColour);
  layer([&](std::size_t i) { return half_c_p * g.false_tracks[i]; }, kFalseColour);
  const double line_width = n > 400 ? 0.7 : 1.6;  // dense series: thin line
  svg += fmt::format(
      "<polyline fill=\"none\" stroke=\"#111\" stroke-width=\"{}\" "
      "stroke-linejoin=\"round\" points=\"{}\"/>\n",
      line_width, polyline(g.time, g.gospa, axes.x, axes.y));

  const auto box = [](std::string_view colour) {
    return fmt::format(
        "<rect x=\"0\" y=\"-6\" width=\"28\" height=\"12\" fill=\"{}\" "
        "fill-opacity=\"0.75\"/>",
        colour);
  };
  draw_legend(svg, kTimeLeft + kTimeWidth / 2, kLegendY,
              {{"<line x1=\"0\" y1=\"0\" x2=\"28\" y2=\"0\" stroke=\"#111\" "
                "stroke-width=\"1.6\"/>",
                "GOSPA"},
               {box(kLocColour), "localisation share"},
               {box(kMissColour), "missed share"},
               {box(kFalseColour), "false share"}});
}

}  // namespace

std::string render_evaluation_svg(const EvaluationPlot& plot) {
  std::string svg = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"{2}\" y=\"38\" font-size=\"22\" font-weight=\"bold\">{3}</text>\n"
      "<text x=\"{2}\" y=\"66\" font-size=\"15\" fill=\"#444\">{4}</text>\n",
      kWidth, kHeight, kMapLeft - 60, escape(plot.title), escape(plot.subtitle));
  svg += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"16\" font-weight=\"bold\" "
      "text-anchor=\"middle\">Truth and scored tracks</text>\n",
      kMapLeft + kPanelSize / 2, kPanelTop - 12);
  svg += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"16\" font-weight=\"bold\" "
      "text-anchor=\"middle\">GOSPA per scan (c = {} m, p = {}, alpha = 2)</text>\n",
      kTimeLeft + kTimeWidth / 2, kPanelTop - 12, plot.cutoff, plot.order);
  draw_map(svg, plot);
  draw_gospa(svg, plot);
  svg += "</svg>\n";
  return svg;
}

}  // namespace skytrack::io
