#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "skytrack/io/svg_plot.hpp"

namespace skytrack::io {
namespace {

using ::testing::HasSubstr;

EvaluationPlot sample_plot() {
  EvaluationPlot plot;
  plot.title = "truth <against> tracks & more";
  plot.subtitle = "2 scans";
  plot.truths = {{1, {0.0, 1000.0}, {0.0, 500.0}}};
  plot.tracks = {{12, {10.0, 990.0}, {5.0, 510.0}}};
  plot.gospa = {{0.0, 1.0}, {12.0, 70.7}, {144.0, 0.0}, {0.0, 1.0}, {0.0, 0.0}};
  return plot;
}

TEST(SvgPlot, IsWellFormedXmlWithEscapedText) {
  const std::string svg = render_evaluation_svg(sample_plot());
  EXPECT_THAT(svg, HasSubstr("<svg"));
  EXPECT_THAT(svg, HasSubstr("</svg>"));
  EXPECT_THAT(svg, HasSubstr("truth &lt;against&gt; tracks &amp; more"));
  // Every opened element is closed: count tags the simple way.
  std::size_t opened = 0, closed = 0;
  for (std::size_t i = 0; (i = svg.find('<', i)) != std::string::npos; ++i) {
    if (svg.compare(i, 2, "</") == 0) {
      ++closed;
    } else if (svg.compare(i, 2, "<?") != 0 && svg.compare(i, 2, "<!") != 0) {
      const std::size_t end = svg.find('>', i);
      if (svg[end - 1] != '/') ++opened;
    }
  }
  EXPECT_EQ(opened, closed);
}

TEST(SvgPlot, EmptyRunStillRenders) {
  const std::string svg = render_evaluation_svg(EvaluationPlot{});
  EXPECT_THAT(svg, HasSubstr("</svg>"));
}

}  // namespace
}  // namespace skytrack::io
