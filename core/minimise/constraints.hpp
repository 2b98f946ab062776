// Held scalar constraints c_k(x) = target_k on a state of many points (the bilayer's area and the
// cell's volume while a shape is minimised). Two operations, the ones a constrained minimiser
// needs (as SHAKE/RATTLE do for molecular dynamics):
// - project a vector field (a force, a velocity) onto the constraints' tangent space, removing
//   its components along the gradients grad c_k (a k x k Gram system);
// - restore the constraints after a step, by Newton iterations along the gradients.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "common/vec3.hpp"

namespace rbcsim::minimise {

struct Constraint {
  std::string name;  // for diagnostics ("membrane area")
  // Returns c(x) and overwrites `gradient` (one entry per point) with dc/dx.
  std::function<double(std::span<const Vec3> positions, std::span<Vec3> gradient)> evaluate;
  double target = 0.0;
  // Restored when |c - target| <= tolerance (in c's unit).
  double tolerance = 0.0;
};

class ConstraintSet {
 public:
  ConstraintSet(std::vector<Constraint> constraints, std::size_t point_count);

  bool empty() const { return constraints_.empty(); }
  std::span<const Constraint> constraints() const { return constraints_; }
  void set_target(std::size_t k, double target) { constraints_[k].target = target; }

  // vectors -= sum_k m_k grad c_k with the m_k that leave `vectors` orthogonal to every gradient.
  void project(std::span<const Vec3> positions, std::span<Vec3> vectors);
  // Moves `positions` along the gradients until every |c_k - target_k| <= tolerance_k; throws
  // RuntimeFailure naming the constraint when 20 Newton iterations do not get there.
  void restore(std::span<Vec3> positions);
  // c_k - target_k at `positions`.
  std::vector<double> residuals(std::span<const Vec3> positions);

 private:
  // Evaluates every constraint at `positions` into values_ and gradients_.
  void evaluate(std::span<const Vec3> positions);
  // Solves Gram(gradients) m = rhs in place (Gaussian elimination, k is 2 or 3).
  void solve_gram(std::vector<double>& rhs) const;

  std::vector<Constraint> constraints_;
  std::vector<double> values_;
  std::vector<std::vector<Vec3>> gradients_;
};

}  // namespace rbcsim::minimise
