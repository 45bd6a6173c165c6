#include "svg_writer.hpp"

#include <fstream>
#include <map>
#include <string_view>

#include <fmt/format.h>

namespace group_mc {
namespace {

constexpr double kSize = 700.0, kMargin = 50.0;
constexpr std::string_view kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                         "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

}  // namespace

bool write_svg(const std::string& path, const Scenario& sc, const RunRecord& run) {
  std::ofstream out(path);
  if (!out) {
    return false;
  }
  const double a = sc.spec.area_half;
  const auto px = [&](double x) { return kMargin + (x + a) / (2 * a) * kSize; };
  const auto py = [&](double y) { return kMargin + (a - y) / (2 * a) * kSize; };
  out << fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"{0}\" height=\"{1}\" "
      "fill=\"white\"/>\n",
      kSize + 2 * kMargin + 160, kSize + 2 * kMargin);
  out << fmt::format(
      "<rect x=\"{0}\" y=\"{0}\" width=\"{1}\" height=\"{1}\" fill=\"none\" stroke=\"#999\"/>\n",
      kMargin, kSize);
  out << fmt::format(
      "<text x=\"{}\" y=\"30\">Paper 000 experiment 1, one run: truth (black) and LBP-PHD "
      "groups (colour = group number); grey: plots</text>\n",
      kMargin);
  for (double t = -a; t <= a + 1e-9; t += 500.0) {
    out << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{:.0f}</text>\n", px(t),
                       kMargin + kSize + 18, t);
    out << fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{:.0f}</text>\n", kMargin - 6,
                       py(t) + 4, t);
  }
  for (const Scan& scan : sc.scans) {
    for (const auto& p : scan.plots) {
      out << fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"0.8\" fill=\"#bbb\"/>\n",
                         px(p.x()), py(p.y()));
    }
  }
  for (const TruthGroup& g : sc.groups) {
    std::string points;
    for (int k = g.first; k <= g.last; ++k) {
      const auto& x = g.state[static_cast<std::size_t>(k - 1)];
      points += fmt::format("{:.1f},{:.1f} ", px(x(0)), py(x(2)));
    }
    out << fmt::format(
        "<polyline points=\"{}\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.5\"/>\n", points);
    const auto& x0 = g.state[static_cast<std::size_t>(g.first - 1)];
    out << fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" fill=\"#222\">truth {}</text>\n",
                       px(x0(0)) + 6, py(x0(2)) - 6, g.id);
  }
  std::map<std::uint32_t, int> colour;
  for (const ScanEstimates& s : run.scans) {
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
      const std::uint32_t label = s.labels[i];
      const int c = colour.emplace(label, static_cast<int>(colour.size())).first->second;
      out << fmt::format(
          "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3.5\" fill=\"none\" stroke=\"{}\" "
          "stroke-width=\"1.5\"/>\n",
          px(s.positions[i](0)), py(s.positions[i](1)), kPalette[c % 10]);
    }
  }
  int row = 0;
  for (const auto& [label, c] : colour) {
    out << fmt::format(
        "<circle cx=\"{}\" cy=\"{}\" r=\"4\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\"/>"
        "<text x=\"{}\" y=\"{}\">group {}</text>\n",
        kMargin + kSize + 25, kMargin + 20 + 20 * row, kPalette[c % 10], kMargin + kSize + 35,
        kMargin + 24 + 20 * row, label);
    ++row;
  }
  out << "</svg>\n";
  return static_cast<bool>(out);
}

}  // namespace group_mc
