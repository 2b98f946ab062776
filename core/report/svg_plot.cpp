#include "report/svg_plot.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>

#include "report/markup.hpp"

namespace rbcsim::report::svg {
namespace {

// Layout in SVG user units (pixels at 100 % zoom).
constexpr double kWidth = 640;
constexpr double kPlotLeft = 80;  // room for the y tick labels and the rotated y label
constexpr double kPlotRight = kWidth - 24;
constexpr double kTitleHeight = 36;
constexpr double kPlotHeight = 300;
constexpr double kAxisHeight = 54;  // x tick labels and the x label below the plot area
constexpr double kLegendLineHeight = 18;
constexpr double kLegendSwatchWidth = 30;
constexpr double kMarkerRadius = 3.5;
constexpr double kErrorCapHalfWidth = 3;
constexpr double kBarChartLeft = 24;
constexpr double kBarChartRight = kWidth - 100;  // room for the value after the longest bar
constexpr double kBarRowHeight = 36;             // label line, bar, gap
constexpr double kBarThickness = 15;

constexpr std::string_view kGridColour = "#dddddd";
constexpr std::string_view kAxisColour = "#333333";

std::string fixed(double value, int decimals) {
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                    std::chars_format::fixed, decimals);
  return std::string(buffer.data(), result.ptr);
}

// Coordinates with two decimals: precise to 1/100 pixel and byte-for-byte reproducible.
std::string coordinate(double value) { return fixed(value, 2); }

std::string attribute(std::string_view name, std::string_view value) {
  return concat(" ", name, "=\"", escape_xml(value), "\"");
}

std::string attribute(std::string_view name, double value) {
  return attribute(name, coordinate(value));
}

std::string text_element(double x, double y, std::string_view text, std::string_view extra) {
  return concat("<text", attribute("x", x), attribute("y", y), extra, ">", escape_xml(text),
                "</text>\n");
}

std::string line_element(double x1, double y1, double x2, double y2, std::string_view extra = "") {
  return concat("<line", extra, attribute("x1", x1), attribute("y1", y1), attribute("x2", x2),
                attribute("y2", y2), "/>\n");
}

// A linear map from data values to pixels over the span of `ticks`.
struct Scale {
  Ticks ticks;
  double pixel_at_first;
  double pixel_at_last;
  double pixel(double value) const {
    const double fraction = (value - ticks.first) / (ticks.last() - ticks.first);
    return pixel_at_first + fraction * (pixel_at_last - pixel_at_first);
  }
};

struct Extent {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  void include(double value) {
    if (!std::isfinite(value)) return;
    low = std::min(low, value);
    high = std::max(high, value);
  }
  bool empty() const { return low > high; }
};

// Ticks over the extent; an empty extent becomes [0, 1] and a single value gets a margin.
Ticks ticks_for(Extent extent) {
  if (extent.empty()) return nice_ticks(0.0, 1.0);
  if (extent.low == extent.high) {
    const double margin = extent.low != 0 ? 0.1 * std::abs(extent.low) : 1.0;
    return nice_ticks(extent.low - margin, extent.high + margin);
  }
  return nice_ticks(extent.low, extent.high);
}

std::string svg_open(double height, std::string_view title) {
  return concat("<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\"",
                attribute("width", kWidth), attribute("height", height),
                attribute("viewBox", concat("0 0 ", coordinate(kWidth), " ", coordinate(height))),
                " role=\"img\"", attribute("aria-label", title),
                " font-family=\"sans-serif\" font-size=\"12\">\n<title>", escape_xml(title),
                "</title>\n",
                text_element(kWidth / 2, 22, title,
                             " class=\"plot-title\" text-anchor=\"middle\" font-size=\"14\" "
                             "font-weight=\"bold\""));
}

// Vertical grid lines, tick labels below `bottom` and the axis label under them.
std::string x_axis(const Scale& x, double top, double bottom, std::string_view label) {
  std::string grid = concat("<g class=\"grid\"", attribute("stroke", kGridColour), ">\n");
  std::string labels = "<g class=\"tick-labels\" text-anchor=\"middle\">\n";
  for (int i = 0; i <= x.ticks.intervals; ++i) {
    const double value = x.ticks.first + i * x.ticks.step;
    grid += line_element(x.pixel(value), top, x.pixel(value), bottom);
    labels += text_element(x.pixel(value), bottom + 17, tick_label(value, x.ticks.step), "");
  }
  const double middle = (x.pixel_at_first + x.pixel_at_last) / 2;
  return concat(
      grid, "</g>\n", labels, "</g>\n",
      text_element(middle, bottom + 40, label, " class=\"axis-label\" text-anchor=\"middle\""));
}

// Horizontal grid lines, tick labels left of `left` and the rotated axis label.
std::string y_axis(const Scale& y, double left, double right, std::string_view label) {
  std::string grid = concat("<g class=\"grid\"", attribute("stroke", kGridColour), ">\n");
  std::string labels = "<g class=\"tick-labels\" text-anchor=\"end\">\n";
  for (int i = 0; i <= y.ticks.intervals; ++i) {
    const double value = y.ticks.first + i * y.ticks.step;
    grid += line_element(left, y.pixel(value), right, y.pixel(value));
    labels += text_element(left - 6, y.pixel(value) + 4, tick_label(value, y.ticks.step), "");
  }
  const double middle = (y.pixel_at_first + y.pixel_at_last) / 2;
  const auto rotate = attribute("transform", concat("rotate(-90 18 ", coordinate(middle), ")"));
  return concat(grid, "</g>\n", labels, "</g>\n",
                text_element(18, middle, label,
                             concat(" class=\"axis-label\" text-anchor=\"middle\"", rotate)));
}

std::string polygon_path(double x, double y, std::initializer_list<std::array<double, 2>> offsets) {
  std::string path;
  for (const auto& [dx, dy] : offsets) {
    path += concat(path.empty() ? "M" : " L", coordinate(x + dx), " ", coordinate(y + dy));
  }
  return concat("<path class=\"marker\"", attribute("d", concat(path, " Z")), "/>\n");
}

std::string marker_element(Marker marker, double x, double y) {
  const double r = kMarkerRadius;
  switch (marker) {
    case Marker::none:
      return "";
    case Marker::circle:
      return concat("<circle class=\"marker\"", attribute("cx", x), attribute("cy", y),
                    attribute("r", r), "/>\n");
    case Marker::square:
      return concat("<rect class=\"marker\"", attribute("x", x - r), attribute("y", y - r),
                    attribute("width", 2 * r), attribute("height", 2 * r), "/>\n");
    case Marker::triangle:
      return polygon_path(x, y, {{0, -1.3 * r}, {1.2 * r, 0.9 * r}, {-1.2 * r, 0.9 * r}});
    case Marker::diamond:
      return polygon_path(x, y, {{0, -1.4 * r}, {1.4 * r, 0}, {0, 1.4 * r}, {-1.4 * r, 0}});
  }
  return "";
}

std::string dash_attribute(bool dashed) { return dashed ? " stroke-dasharray=\"6 4\"" : ""; }

bool finite(const PlotPoint& point) { return std::isfinite(point.x) && std::isfinite(point.y); }

// One polyline per run of finite points.
std::string series_lines(const Series& series, const Scale& x, const Scale& y) {
  std::string lines;
  std::string points;
  const auto flush = [&] {
    if (points.find(' ') != std::string::npos) {  // two points at least
      lines += concat("<polyline fill=\"none\" stroke-width=\"1.8\"", dash_attribute(series.dashed),
                      attribute("points", points), "/>\n");
    }
    points.clear();
  };
  for (const auto& point : series.points) {
    if (!finite(point)) {
      flush();
      continue;
    }
    if (!points.empty()) points += ' ';
    points += concat(coordinate(x.pixel(point.x)), ",", coordinate(y.pixel(point.y)));
  }
  flush();
  return lines;
}

std::string error_bar(const PlotPoint& point, const Scale& x, const Scale& y) {
  const double px = x.pixel(point.x);
  const double low = y.pixel(point.y - point.y_error);
  const double high = y.pixel(point.y + point.y_error);
  const std::string cap_left = coordinate(px - kErrorCapHalfWidth);
  const std::string cap_width = coordinate(2 * kErrorCapHalfWidth);
  const auto path = concat("M", coordinate(px), " ", coordinate(low), " V", coordinate(high), " M",
                           cap_left, " ", coordinate(low), " h", cap_width, " M", cap_left, " ",
                           coordinate(high), " h", cap_width);
  return concat("<path class=\"error-bar\" fill=\"none\"", attribute("d", path), "/>\n");
}

std::string series_group(const Series& series, const Scale& x, const Scale& y) {
  std::string group =
      concat("<g class=\"series\"", attribute("data-label", series.label),
             attribute("stroke", series.colour), attribute("fill", series.colour), ">\n");
  if (series.line) group += series_lines(series, x, y);
  for (const auto& point : series.points) {
    if (finite(point) && point.y_error > 0) group += error_bar(point, x, y);
  }
  for (const auto& point : series.points) {
    if (finite(point)) group += marker_element(series.marker, x.pixel(point.x), y.pixel(point.y));
  }
  return group.append("</g>\n");
}

std::string legend(const std::vector<Series>& series, double top) {
  std::string entries = "<g class=\"legend\">\n";
  for (std::size_t i = 0; i < series.size(); ++i) {
    const auto& entry = series[i];
    const double y = top + static_cast<double>(i) * kLegendLineHeight;
    entries += concat("<g class=\"legend-entry\"", attribute("data-label", entry.label),
                      attribute("stroke", entry.colour), attribute("fill", entry.colour), ">\n");
    if (entry.line) {
      entries += line_element(kPlotLeft, y, kPlotLeft + kLegendSwatchWidth, y,
                              concat(" stroke-width=\"1.8\"", dash_attribute(entry.dashed)));
    }
    entries += marker_element(entry.marker, kPlotLeft + kLegendSwatchWidth / 2, y);
    entries += text_element(kPlotLeft + kLegendSwatchWidth + 8, y + 4, entry.label,
                            " stroke=\"none\" fill=\"#000000\"");
    entries += "</g>\n";
  }
  return entries.append("</g>\n");
}

std::string frame(double left, double top, double right, double bottom) {
  return concat("<rect class=\"frame\" fill=\"none\"", attribute("stroke", kAxisColour),
                attribute("x", left), attribute("y", top), attribute("width", right - left),
                attribute("height", bottom - top), "/>\n");
}

std::string no_data_note(double x, double y) {
  return text_element(x, y, "no data",
                      " class=\"no-data\" text-anchor=\"middle\" fill=\"#777777\"");
}

}  // namespace

std::string palette_colour(std::size_t index) {
  // Okabe and Ito (2008) without its yellow, which is unreadable on white.
  constexpr std::array<std::string_view, 6> kPalette{"#0072B2", "#D55E00", "#009E73",
                                                     "#CC79A7", "#E69F00", "#56B4E9"};
  return std::string(kPalette[index % kPalette.size()]);
}

Ticks nice_ticks(double low, double high, int target_intervals) {
  const double raw_step = (high - low) / target_intervals;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw_step)));
  const double residual = raw_step / magnitude;
  const double multiple = residual < 1.5 ? 1 : residual < 3 ? 2 : residual < 7 ? 5 : 10;
  const double step = multiple * magnitude;
  // The tolerance keeps a bound that is a tick up to rounding (2.0000000001 steps) from adding
  // a whole empty interval.
  constexpr double kRoundingTolerance = 1e-9;
  const double first = std::floor(low / step + kRoundingTolerance);
  const double last = std::ceil(high / step - kRoundingTolerance);
  return {first * step, step, static_cast<int>(last - first)};
}

std::string tick_label(double value, double step) {
  if (std::abs(value) < 1e-9 * step) return "0";  // -1e-17 from accumulated rounding is zero
  const int step_exponent = static_cast<int>(std::floor(std::log10(step) + 1e-9));
  const int value_exponent = static_cast<int>(std::floor(std::log10(std::abs(value))));
  if (step_exponent >= -4 && value_exponent < 6) return fixed(value, std::max(0, -step_exponent));
  std::array<char, 64> buffer{};
  const auto result =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                    std::chars_format::scientific, std::max(0, value_exponent - step_exponent));
  return std::string(buffer.data(), result.ptr);
}

std::string render_line_plot(const LinePlot& plot) {
  Extent x_extent;
  Extent y_extent;
  for (const auto& series : plot.series) {
    for (const auto& point : series.points) {
      if (!finite(point)) continue;
      x_extent.include(point.x);
      y_extent.include(point.y - point.y_error);
      y_extent.include(point.y + point.y_error);
    }
  }
  const double bottom = kTitleHeight + kPlotHeight;
  const Scale x{ticks_for(x_extent), kPlotLeft, kPlotRight};
  const Scale y{ticks_for(y_extent), bottom, kTitleHeight};
  const double legend_top = bottom + kAxisHeight + 12;
  const double height =
      legend_top + static_cast<double>(plot.series.size()) * kLegendLineHeight + 4;

  std::string svg = svg_open(height, plot.title);
  svg += x_axis(x, kTitleHeight, bottom, plot.x_label);
  svg += y_axis(y, kPlotLeft, kPlotRight, plot.y_label);
  svg += frame(kPlotLeft, kTitleHeight, kPlotRight, bottom);
  if (x_extent.empty()) svg += no_data_note((kPlotLeft + kPlotRight) / 2, kTitleHeight + 40);
  for (const auto& series : plot.series) svg += series_group(series, x, y);
  svg += legend(plot.series, legend_top);
  return svg.append("</svg>\n");
}

std::string render_bar_chart(const BarChart& chart) {
  Extent extent;
  extent.include(0.0);  // bars start at zero
  for (const auto& bar : chart.bars) extent.include(bar.value + bar.error);
  const Scale x{ticks_for(extent), kBarChartLeft, kBarChartRight};
  const double bottom = kTitleHeight + static_cast<double>(chart.bars.size()) * kBarRowHeight + 6;
  const double height = bottom + kAxisHeight + 4;

  std::string svg = svg_open(height, chart.title);
  svg += x_axis(x, kTitleHeight, bottom, chart.value_label);
  if (chart.bars.empty())
    svg += no_data_note((kBarChartLeft + kBarChartRight) / 2, kTitleHeight + 4);
  for (std::size_t i = 0; i < chart.bars.size(); ++i) {
    const auto& bar = chart.bars[i];
    const double row_top = kTitleHeight + static_cast<double>(i) * kBarRowHeight;
    svg += concat("<g class=\"bar\"", attribute("data-label", bar.label), ">\n");
    svg += text_element(kBarChartLeft + 4, row_top + 15, bar.label, "");
    double value_x = x.pixel(0.0);
    if (std::isfinite(bar.value)) {
      const double start = std::min(x.pixel(0.0), x.pixel(bar.value));
      value_x = std::max(x.pixel(0.0), x.pixel(bar.value));
      svg += concat("<rect", attribute("fill", bar.colour), attribute("x", start),
                    attribute("y", row_top + 18), attribute("width", value_x - start),
                    attribute("height", kBarThickness), "/>\n");
    }
    std::string value_text = format_significant(bar.value);
    if (bar.error > 0.0 && std::isfinite(bar.value)) {
      const double low = x.pixel(bar.value - bar.error);
      const double high = x.pixel(bar.value + bar.error);
      const double middle = row_top + 18 + kBarThickness / 2;
      svg += concat("<g class=\"error-bar\"", attribute("stroke", kAxisColour), ">",
                    line_element(low, middle, high, middle, ""),
                    line_element(low, middle - 4, low, middle + 4, ""),
                    line_element(high, middle - 4, high, middle + 4, ""), "</g>\n");
      value_x = std::max(value_x, high);
      value_text += " +- " + format_significant(bar.error, 2);
    }
    svg += text_element(value_x + 6, row_top + 30, value_text, " class=\"bar-value\"");
    svg += "</g>\n";
  }
  svg += line_element(kBarChartLeft, bottom, kBarChartRight, bottom,
                      attribute("stroke", kAxisColour));  // the value axis
  return svg.append("</svg>\n");
}

}  // namespace rbcsim::report::svg
