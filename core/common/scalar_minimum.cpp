#include "common/scalar_minimum.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace rbcsim {
namespace {

constexpr double kGoldenRatio = 1.618033988749895;
constexpr double kGoldenSection = 0.3819660112501051;  // 2 - golden ratio: the section's step

struct Sample {
  double x;
  double value;
};

class CountedFunction {
 public:
  explicit CountedFunction(const std::function<double(double)>& function) : function_(function) {}
  Sample operator()(double x) {
    const Sample sample{x, function_(x)};
    if (evaluations_++ == 0 || sample.value < best_.value) best_ = sample;
    return sample;
  }
  int evaluations() const { return evaluations_; }
  const Sample& best() const { return best_; }

 private:
  const std::function<double(double)>& function_;
  int evaluations_ = 0;
  Sample best_{0.0, 0.0};
};

struct Bracket {
  double low;
  Sample best;  // low < best.x < high, below the function at both ends
  double high;
};

// Downhill from `start` in golden-ratio widening steps until the function rises.
std::optional<Bracket> bracket_minimum(CountedFunction& function, double start,
                                       const ScalarMinimumSettings& settings) {
  auto previous = function(start);
  auto current = function(start + settings.initial_step);
  if (!(current.value < previous.value)) std::swap(previous, current);  // downhill the other way
  if (!std::isfinite(current.value)) return std::nullopt;  // neither side could be evaluated
  auto next = function(current.x + kGoldenRatio * (current.x - previous.x));
  while (next.value < current.value) {
    if (function.evaluations() >= settings.max_evaluations) return std::nullopt;
    previous = std::exchange(current, next);
    next = function(current.x + kGoldenRatio * (current.x - previous.x));
  }
  return Bracket{std::min(previous.x, next.x), current, std::max(previous.x, next.x)};
}

// Brent's step from the best point x towards the vertex of the parabola through x, w and v (the
// three best points), or nothing when the parabola is not trusted: points that cannot be
// evaluated, a vertex outside the bracket, or a step not smaller than half the step before last
// (the parabola is then not converging, and golden sections are surer).
std::optional<double> parabolic_step(const Sample& x, const Sample& w, const Sample& v,
                                     double step_before_last, double low, double high) {
  if (!std::isfinite(w.value) || !std::isfinite(v.value)) return std::nullopt;
  const double r = (x.x - w.x) * (x.value - v.value);
  double q = (x.x - v.x) * (x.value - w.value);
  double p = (x.x - v.x) * q - (x.x - w.x) * r;
  q = 2.0 * (q - r);
  if (q > 0.0) p = -p;
  q = std::abs(q);
  const bool trusted = std::abs(p) < std::abs(0.5 * q * step_before_last) && p > q * (low - x.x) &&
                       p < q * (high - x.x);
  if (!trusted) return std::nullopt;
  return p / q;
}

}  // namespace

ScalarMinimum find_scalar_minimum(const std::function<double(double)>& function, double start,
                                  const ScalarMinimumSettings& settings) {
  CountedFunction counted(function);
  const auto bracket = bracket_minimum(counted, start, settings);
  if (!bracket) return {counted.best().x, counted.best().value, counted.evaluations(), false};
  double low = bracket->low;
  double high = bracket->high;
  Sample x = bracket->best;  // the best point so far
  Sample w = x;              // the second best
  Sample v = x;              // the previous w
  double step = 0.0;         // the last step taken
  double step_before_last = 0.0;
  // Half the wanted accuracy: at the end x is within twice this of both bracket ends.
  const double tolerance = 0.5 * settings.tolerance;
  while (counted.evaluations() < settings.max_evaluations) {
    const double middle = 0.5 * (low + high);
    if (std::abs(x.x - middle) <= 2.0 * tolerance - 0.5 * (high - low)) {
      return {x.x, x.value, counted.evaluations(), true};
    }
    std::optional<double> parabolic;
    if (std::abs(step_before_last) > tolerance) {
      parabolic = parabolic_step(x, w, v, step_before_last, low, high);
      step_before_last = step;
    }
    if (parabolic) {
      step = *parabolic;
      const double target = x.x + step;
      // Not closer than the tolerance to the bracket ends.
      if (target - low < 2.0 * tolerance || high - target < 2.0 * tolerance) {
        step = std::copysign(tolerance, middle - x.x);
      }
    } else {
      step_before_last = (x.x >= middle ? low : high) - x.x;
      step = kGoldenSection * step_before_last;
    }
    // A step below the tolerance cannot tell two points apart: take the tolerance.
    const auto trial =
        counted(x.x + (std::abs(step) >= tolerance ? step : std::copysign(tolerance, step)));
    if (trial.value <= x.value) {
      (trial.x >= x.x ? low : high) = x.x;
      v = std::exchange(w, std::exchange(x, trial));
    } else {
      (trial.x < x.x ? low : high) = trial.x;
      if (trial.value <= w.value || w.x == x.x) {
        v = std::exchange(w, trial);
      } else if (trial.value <= v.value || v.x == x.x || v.x == w.x) {
        v = trial;
      }
    }
  }
  return {x.x, x.value, counted.evaluations(), false};
}

}  // namespace rbcsim
