#include "report/svg_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/xml_document.hpp"

namespace {

using namespace rbcsim::report::svg;
using rbcsim::testing::parse_xml;
using rbcsim::testing::XmlDocument;

double number_attribute(const XmlDocument& svg, std::size_t element, const std::string& name) {
  return std::stod(svg.elements[element].attribute(name));
}

TEST(NiceTicks, EncloseTheRangeWithRoundSteps) {
  const std::vector<std::pair<double, double>> ranges{
      {0, 193},       {4.2, 15.3}, {0, 1},       {-3.7, 2.2},  {1e-4, 1.3e-3},
      {2e-19, 3e-19}, {0, 2000},   {0.99, 1.01}, {-1e6, -2e5}, {7.74, 7.75}};
  for (const auto& [low, high] : ranges) {
    const auto ticks = nice_ticks(low, high);
    EXPECT_LE(ticks.first, low) << low << ".." << high;
    EXPECT_GE(ticks.last(), high) << low << ".." << high;
    EXPECT_GE(ticks.intervals, 3) << low << ".." << high;
    EXPECT_LE(ticks.intervals, 10) << low << ".." << high;
    // The step is 1, 2 or 5 times a power of ten, and the first tick a multiple of it.
    const double mantissa = ticks.step / std::pow(10.0, std::floor(std::log10(ticks.step)));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                std::abs(mantissa - 5) < 1e-9)
        << ticks.step;
    const double steps_to_first = ticks.first / ticks.step;
    EXPECT_NEAR(steps_to_first, std::round(steps_to_first), 1e-9);
  }
}

TEST(NiceTicks, ExactBoundsAddNoEmptyInterval) {
  const auto ticks = nice_ticks(0, 10);
  EXPECT_EQ(ticks.first, 0);
  EXPECT_EQ(ticks.step, 2);
  EXPECT_EQ(ticks.intervals, 5);
}

TEST(TickLabel, JustEnoughDecimals) {
  EXPECT_EQ(tick_label(150, 50), "150");
  EXPECT_EQ(tick_label(0.25, 0.05), "0.25");
  EXPECT_EQ(tick_label(1.5, 0.5), "1.5");
  EXPECT_EQ(tick_label(2, 0.5), "2.0");
  EXPECT_EQ(tick_label(0.0004, 0.0002), "0.0004");
  EXPECT_EQ(tick_label(-1e-17, 0.1), "0");  // rounding residue at zero
  EXPECT_EQ(tick_label(2e-5, 1e-5), "2e-05");
  EXPECT_EQ(tick_label(2.5e-19, 5e-20), "2.5e-19");
  EXPECT_EQ(tick_label(3e6, 1e6), "3e+06");
}

// Points on the tick bounds land on the edges of the plot frame; a point in the middle lands in
// the middle; an error bar of +-1 on a 0..10 axis spans a fifth of the frame's height.
TEST(LinePlot, MapsDataOntoTheFrame) {
  const LinePlot plot{
      "Mapping", "x (um)", "y (pN)", {{"data", {{0, 0}, {5, 5, 1}, {10, 10}}, palette_colour(0)}}};
  const auto svg = parse_xml(render_line_plot(plot));
  ASSERT_EQ(svg.error, "");
  const auto frame = svg.find("rect", "frame")[0];
  const double left = number_attribute(svg, frame, "x");
  const double top = number_attribute(svg, frame, "y");
  const double width = number_attribute(svg, frame, "width");
  const double height = number_attribute(svg, frame, "height");

  const auto line = svg.find("polyline");
  ASSERT_EQ(line.size(), 1u);
  double x0, y0, x1, y1, x2, y2;
  ASSERT_EQ(std::sscanf(svg.elements[line[0]].attribute("points").c_str(),
                        "%lf,%lf %lf,%lf %lf,%lf", &x0, &y0, &x1, &y1, &x2, &y2),
            6);
  EXPECT_NEAR(x0, left, 0.01);
  EXPECT_NEAR(y0, top + height, 0.01);
  EXPECT_NEAR(x1, left + width / 2, 0.01);
  EXPECT_NEAR(y1, top + height / 2, 0.01);
  EXPECT_NEAR(x2, left + width, 0.01);
  EXPECT_NEAR(y2, top, 0.01);

  const auto bars = svg.find("path", "error-bar");
  ASSERT_EQ(bars.size(), 1u);
  double bar_x, bar_low, bar_high;
  ASSERT_EQ(std::sscanf(svg.elements[bars[0]].attribute("d").c_str(), "M%lf %lf V%lf", &bar_x,
                        &bar_low, &bar_high),
            3);
  EXPECT_NEAR(bar_x, x1, 0.01);
  EXPECT_NEAR(bar_low - bar_high, height / 5, 0.01);
  EXPECT_EQ(svg.find("circle", "marker").size(), 3u + 1u);  // three points and the legend swatch
}

TEST(LinePlot, LabelsAxesTicksAndLegend) {
  const LinePlot plot{
      "Two series",
      "force (pN)",
      "diameter (µm)",
      {{"first", {{0, 1}, {200, 2}}, palette_colour(0)},
       {"second", {{0, 2}, {200, 1}}, palette_colour(1), Marker::square, true, true}}};
  const auto svg = parse_xml(render_line_plot(plot));
  ASSERT_EQ(svg.error, "");
  std::vector<std::string> texts;
  for (const auto i : svg.find("text")) texts.push_back(svg.elements[i].text);
  for (const std::string expected : {"Two series", "force (pN)", "diameter (µm)", "0", "50", "200",
                                     "1.0", "2.0", "first", "second"}) {
    EXPECT_NE(std::find(texts.begin(), texts.end(), expected), texts.end()) << expected;
  }
  EXPECT_EQ(svg.labels("legend-entry", -1), (std::vector<std::string>{"first", "second"}));
  EXPECT_EQ(svg.find("rect", "marker").size(), 3u);  // two data points and the legend swatch
  EXPECT_EQ(svg.elements[svg.find("polyline")[1]].attribute("stroke-dasharray"), "6 4");
}

TEST(LinePlot, NonFinitePointsBreakTheLine) {
  const LinePlot plot{
      "Gap",
      "x",
      "y",
      {{"gappy", {{0, 0}, {1, 1}, {NAN, 2}, {3, INFINITY}, {4, 4}, {5, 5}}, palette_colour(0)}}};
  const auto svg = parse_xml(render_line_plot(plot));
  ASSERT_EQ(svg.error, "");
  EXPECT_EQ(svg.find("polyline").size(), 2u);
  EXPECT_EQ(svg.find("circle", "marker").size(), 4u + 1u);  // four points and the legend swatch
}

TEST(LinePlot, EscapesLabelsAndSaysWhenThereIsNoData) {
  const std::string hostile = "<a href=\"x\">&'</a>";
  const LinePlot plot{hostile, hostile, hostile, {{hostile, {}, palette_colour(0)}}};
  const auto svg = parse_xml(render_line_plot(plot));
  ASSERT_EQ(svg.error, "");
  EXPECT_EQ(svg.find("a").size(), 0u);
  EXPECT_EQ(svg.elements[svg.find("title")[0]].text, hostile);
  EXPECT_EQ(svg.labels("series", -1), std::vector<std::string>{hostile});
  std::vector<std::string> texts;
  for (const auto i : svg.find("text")) texts.push_back(svg.elements[i].text);
  EXPECT_NE(std::find(texts.begin(), texts.end(), "no data"), texts.end());
}

TEST(BarChart, BarLengthsAreProportionalToValues) {
  const BarChart chart{
      "Transit",
      "transit time (s)",
      {{"discocyte", 1e-3, palette_colour(0)}, {"stomatocyte-II", 2e-3, palette_colour(1)}}};
  const auto svg = parse_xml(render_bar_chart(chart));
  ASSERT_EQ(svg.error, "");
  EXPECT_EQ(svg.labels("bar", -1), (std::vector<std::string>{"discocyte", "stomatocyte-II"}));
  std::vector<double> starts;
  std::vector<double> widths;
  for (const auto bar : svg.find("g", "bar")) {
    const auto rect = svg.find("rect", "", static_cast<long>(bar));
    ASSERT_EQ(rect.size(), 1u);
    starts.push_back(number_attribute(svg, rect[0], "x"));
    widths.push_back(number_attribute(svg, rect[0], "width"));
  }
  EXPECT_EQ(starts[0], starts[1]);  // both start at zero
  EXPECT_NEAR(widths[1] / widths[0], 2.0, 1e-3);
  std::vector<std::string> values;
  for (const auto i : svg.find("text", "bar-value")) values.push_back(svg.elements[i].text);
  EXPECT_EQ(values, (std::vector<std::string>{"0.001", "0.002"}));
}

}  // namespace
