// Plots as inline SVG, written by hand so the report needs no JavaScript and no external asset
// and opens offline: line/scatter plots with axes, ticks, axis labels (with units), a legend and
// vertical error bars, and horizontal bar charts. Output is deterministic (fixed decimals, no
// ids, no clock). Every text is XML-escaped; elements carry classes (series, marker, error-bar,
// bar, legend-entry) and data-label attributes so tests and style sheets can find them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rbcsim::report::svg {

struct PlotPoint {
  double x;
  double y;
  double y_error = 0.0;  // half-length of a vertical error bar; 0 draws none
};

enum class Marker { none, circle, square, triangle, diamond };

struct Series {
  std::string label;
  std::vector<PlotPoint> points;  // non-finite points are left out, breaking the line there
  std::string colour;             // a CSS colour, e.g. palette_colour(i)
  Marker marker = Marker::circle;
  bool line = true;  // join consecutive points
  bool dashed = false;
};

struct LinePlot {
  std::string title;
  std::string x_label;  // with its unit: "force (pN)"
  std::string y_label;
  std::vector<Series> series;
};

struct Bar {
  std::string label;
  double value;
  std::string colour;
  // An ensemble's spread: a whisker value +- error (0: none), printed beside the value.
  double error = 0.0;
};

struct BarChart {
  std::string title;
  std::string value_label;  // with its unit: "transit time (s)"
  std::vector<Bar> bars;    // drawn top to bottom, each with its label above it
};

// The i-th colour of a colour-blind-safe palette (Okabe and Ito), cycling.
std::string palette_colour(std::size_t index);
// Reference (measured) data: near-black, distinct from every palette colour.
inline constexpr std::string_view kReferenceColour = "#222222";

std::string render_line_plot(const LinePlot& plot);
std::string render_bar_chart(const BarChart& chart);

// Axis ticks first, first + step, ..., first + intervals * step: step is 1, 2 or 5 times a power of
// ten, chosen for about `target_intervals` intervals, and the ticks enclose [low, high].
struct Ticks {
  double first;
  double step;
  int intervals;
  double last() const { return first + step * intervals; }
};
Ticks nice_ticks(double low, double high, int target_intervals = 5);

// The label of tick value `value` on an axis of step `step`: just enough decimals to tell the
// ticks apart ("0", "0.25", "150"), scientific notation for very small or large values ("2e-05").
std::string tick_label(double value, double step);

}  // namespace rbcsim::report::svg
