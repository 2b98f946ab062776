#include "config/range.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace rbcsim::config {
namespace {

// Relative slack when deciding whether stop lands on a step: (stop - start)/step is computed in
// floating point, so 0.1:0.3:0.1 gives 1.9999999999999998 steps where 2 are meant.
constexpr double kStepLandingTolerance = 1e-9;

struct RangeItem {
  std::string_view text;
  std::string_view source;

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(std::string(source), "range " + in_quotes(text) + ": " + problem);
  }

  double number(std::string_view word) const {
    while (!word.empty() && word.front() == ' ') word.remove_prefix(1);
    while (!word.empty() && word.back() == ' ') word.remove_suffix(1);
    double value = 0.0;
    const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || result.ec != std::errc() || result.ptr != word.data() + word.size() ||
        !std::isfinite(value)) {
      fail(in_quotes(word) + " is not a number");
    }
    return value;
  }

  std::size_t count(std::string_view word) const {
    const double value = number(word);
    if (value != std::floor(value) || value < 2 ||
        value > static_cast<double>(kMaximumRangeValues)) {
      fail("count must be a whole number from 2 to " + std::to_string(kMaximumRangeValues));
    }
    return static_cast<std::size_t>(value);
  }

  std::vector<double> evenly_spaced(double start, double stop, std::size_t values) const {
    if (start == stop) return {start};
    std::vector<double> list(values);
    const double step = (stop - start) / static_cast<double>(values - 1);
    for (std::size_t i = 0; i < values; ++i) list[i] = start + static_cast<double>(i) * step;
    list.back() = stop;
    return list;
  }

  std::vector<double> stepped(double start, double stop, double step) const {
    if (step == 0.0) fail("step must not be 0");
    const double steps = (stop - start) / step;
    if (steps < 0.0) fail("step " + format_number(step) + " goes away from the stop");
    const double landing = std::round(steps);
    const bool lands = std::abs(steps - landing) <= kStepLandingTolerance * std::max(1.0, steps);
    const double whole_steps = lands ? landing : std::floor(steps);
    if (whole_steps >= static_cast<double>(kMaximumRangeValues)) {
      fail("more than " + std::to_string(kMaximumRangeValues) + " values");
    }
    std::vector<double> list(static_cast<std::size_t>(whole_steps) + 1);
    for (std::size_t i = 0; i < list.size(); ++i) list[i] = start + static_cast<double>(i) * step;
    if (lands) list.back() = stop;
    return list;
  }

  std::vector<double> values(std::size_t default_count) const {
    const auto first_colon = text.find(':');
    if (first_colon == std::string_view::npos) return {number(text)};
    const double start = number(text.substr(0, first_colon));
    const auto rest = text.substr(first_colon + 1);
    const auto second_colon = rest.find(':');
    const auto slash = rest.find('/');
    if (second_colon != std::string_view::npos && slash != std::string_view::npos) {
      fail("use either :step or /count, not both");
    }
    if (second_colon != std::string_view::npos) {
      return stepped(start, number(rest.substr(0, second_colon)),
                     number(rest.substr(second_colon + 1)));
    }
    if (slash != std::string_view::npos) {
      return evenly_spaced(start, number(rest.substr(0, slash)), count(rest.substr(slash + 1)));
    }
    return evenly_spaced(start, number(rest), default_count);
  }
};

}  // namespace

std::vector<double> parse_range(std::string_view text, std::string_view source,
                                std::size_t default_count) {
  if (default_count < 2) throw std::logic_error("parse_range: default_count must be >= 2");
  std::vector<double> list;
  std::size_t start = 0;
  while (true) {
    const auto comma = text.find(',', start);
    const auto item = RangeItem{text.substr(start, comma - start), source}.values(default_count);
    list.insert(list.end(), item.begin(), item.end());
    if (list.size() > kMaximumRangeValues) {
      throw InputError(std::string(source),
                       "more than " + std::to_string(kMaximumRangeValues) + " values");
    }
    if (comma == std::string_view::npos) return list;
    start = comma + 1;
  }
}

}  // namespace rbcsim::config
