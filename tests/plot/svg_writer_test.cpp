// The SVG writer: axes, ticks, legend, escaping, log scales skip what they cannot show.
#include "plot/svg_writer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace softtune::plot {
namespace {

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

TEST(SvgWriter, AxesLegendAndSeries) {
  Plot p{"A & B", make_axis("time", "s"), make_axis("position", "m"), {}, {0.5}};
  p.series.push_back({"first <1>", "m", {0, 1, 2}, {0, 1, 0}, Style::line, false});
  p.series.push_back({"second", "m", {0, 1, 2}, {1, 0, 1}, Style::markers, false});
  const std::string svg = render_svg(p);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("A &amp; B"), std::string::npos);
  EXPECT_NE(svg.find("first &lt;1&gt;"), std::string::npos);
  EXPECT_NE(svg.find("time (s)"), std::string::npos);
  EXPECT_NE(svg.find("position (m)"), std::string::npos);
  EXPECT_EQ(count(svg, "<polyline"), 1u);  // the line series
  EXPECT_EQ(count(svg, "<circle"), 3u);    // the marker series
  EXPECT_EQ(count(svg, "stroke-dasharray=\"6 4\""), 1u);  // the reference line
}

TEST(SvgWriter, LogAxisSkipsNonPositiveAndNonFinite) {
  Plot p{"log", make_axis("x", "", Scale::log), make_axis("y", "", Scale::log), {}, {}};
  p.series.push_back({"s", "", {1, 10, 100, 1000}, {1e-3, 0.0, NAN, 1.0}, Style::line_and_markers, false});
  const std::string svg = render_svg(p);
  EXPECT_EQ(count(svg, "<circle"), 2u);
  EXPECT_EQ(count(svg, "<polyline"), 2u);  // broken at the skipped points
  EXPECT_NE(svg.find(">0.001<"), std::string::npos);
  EXPECT_NE(svg.find("log scale"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

TEST(SvgWriter, StacksPanels) {
  const std::vector<Plot> plots(3, Plot{"p", make_axis("x", ""), make_axis("y", ""), {}, {}});
  const std::string svg = render_svg(plots);
  EXPECT_NE(svg.find("height=\"" + std::to_string(3 * kPanelHeight) + "\""), std::string::npos);
}

}  // namespace
}  // namespace softtune::plot
