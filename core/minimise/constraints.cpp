#include "minimise/constraints.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "minimise/vector_field.hpp"

namespace rbcsim::minimise {
namespace {

constexpr int kMaxRestoreIterations = 20;

}  // namespace

ConstraintSet::ConstraintSet(std::vector<Constraint> constraints, std::size_t point_count)
    : constraints_(std::move(constraints)),
      values_(constraints_.size()),
      gradients_(constraints_.size(), std::vector<Vec3>(point_count)) {}

void ConstraintSet::evaluate(std::span<const Vec3> positions) {
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    values_[k] = constraints_[k].evaluate(positions, gradients_[k]);
  }
}

void ConstraintSet::solve_gram(std::vector<double>& rhs) const {
  const std::size_t n = constraints_.size();
  std::vector<std::vector<double>> gram(n, std::vector<double>(n));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) gram[i][j] = dot(gradients_[i], gradients_[j]);
  }
  for (std::size_t pivot = 0; pivot < n; ++pivot) {
    for (std::size_t row = pivot + 1; row < n; ++row) {
      const double factor = gram[row][pivot] / gram[pivot][pivot];
      for (std::size_t column = pivot; column < n; ++column) {
        gram[row][column] -= factor * gram[pivot][column];
      }
      rhs[row] -= factor * rhs[pivot];
    }
  }
  for (std::size_t row = n; row-- > 0;) {
    for (std::size_t column = row + 1; column < n; ++column)
      rhs[row] -= gram[row][column] * rhs[column];
    rhs[row] /= gram[row][row];
  }
}

void ConstraintSet::project(std::span<const Vec3> positions, std::span<Vec3> vectors) {
  if (constraints_.empty()) return;
  evaluate(positions);
  std::vector<double> multipliers(constraints_.size());
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    multipliers[k] = dot(gradients_[k], vectors);
  }
  solve_gram(multipliers);
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    for (std::size_t i = 0; i < vectors.size(); ++i)
      vectors[i] -= multipliers[k] * gradients_[k][i];
  }
}

void ConstraintSet::restore(std::span<Vec3> positions) {
  if (constraints_.empty()) return;
  // Newton's method along the gradients, damped: a step that does not shrink the largest
  // relative residual is halved (far from the constraint surface its curvature matters).
  auto worst = [this](std::span<const double> steps) {
    double largest = 0.0;
    for (std::size_t k = 0; k < constraints_.size(); ++k) {
      largest = std::max(largest, std::abs(steps[k]) / constraints_[k].tolerance);
    }
    return largest;
  };
  std::vector<Vec3> start(positions.begin(), positions.end());
  std::vector<double> steps(constraints_.size());
  auto measure = [&] {
    evaluate(positions);
    for (std::size_t k = 0; k < constraints_.size(); ++k) {
      steps[k] = constraints_[k].target - values_[k];
    }
    return worst(steps);
  };
  double residual = measure();
  for (int iteration = 0; residual > 1.0; ++iteration) {
    if (iteration == kMaxRestoreIterations) {
      for (std::size_t k = 0; k < constraints_.size(); ++k) {
        if (std::abs(steps[k]) > constraints_[k].tolerance) {
          throw RuntimeFailure("the held " + constraints_[k].name +
                               " could not be restored: off by " + format_significant(-steps[k]) +
                               " after " + std::to_string(kMaxRestoreIterations) +
                               " Newton iterations");
        }
      }
    }
    // The smallest move sum_k s_k grad c_k that changes every c_k by steps[k] to first order.
    solve_gram(steps);
    std::copy(positions.begin(), positions.end(), start.begin());
    const auto gradients = gradients_;
    for (double fraction = 1.0;; fraction *= 0.5) {
      for (std::size_t i = 0; i < positions.size(); ++i) {
        positions[i] = start[i];
        for (std::size_t k = 0; k < constraints_.size(); ++k) {
          positions[i] += fraction * steps[k] * gradients[k][i];
        }
      }
      const auto previous_steps = steps;
      const double next = measure();
      if (next < residual || fraction < 1e-3) {
        residual = next;
        break;
      }
      steps = previous_steps;
    }
  }
}

std::vector<double> ConstraintSet::residuals(std::span<const Vec3> positions) {
  evaluate(positions);
  std::vector<double> result(constraints_.size());
  for (std::size_t k = 0; k < constraints_.size(); ++k)
    result[k] = values_[k] - constraints_[k].target;
  return result;
}

}  // namespace rbcsim::minimise
