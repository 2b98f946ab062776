// The minimiser module on problems with known answers: FIRE on an anisotropic quadratic, the
// same held on a sphere (the minimum is the projection of the target onto it), the retreat from a
// singular limit, the stiffness estimate against a known largest eigenvalue, and the constraint
// projection and restoration.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/errors.hpp"
#include "minimise/constraints.hpp"
#include "minimise/fire.hpp"
#include "minimise/stiffness.hpp"
#include "minimise/vector_field.hpp"

namespace {

using rbcsim::Vec3;
namespace minimise = rbcsim::minimise;

// E = sum_i (k_i / 2) |x_i - t_i|^2 with stiffnesses k_i spread over two decades.
class Springs : public minimise::FireProblem {
 public:
  explicit Springs(std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
      const auto at = static_cast<double>(i);
      targets.emplace_back(std::cos(1.0 + at), std::sin(2.0 * at), 0.1 * at);
      stiffness.push_back(1.0 + 99.0 * static_cast<double>(i) / static_cast<double>(count - 1));
    }
  }
  void forces(std::span<const Vec3> x, std::span<Vec3> f) override {
    for (std::size_t i = 0; i < x.size(); ++i) f[i] = -stiffness[i] * (x[i] - targets[i]);
  }
  double stiffest_mode(std::span<const Vec3> x) override {
    return minimise::estimate_stiffest_mode(
        [this](std::span<const Vec3> p, std::span<Vec3> f) { forces(p, f); }, x, 1e-6);
  }
  std::vector<Vec3> targets;
  std::vector<double> stiffness;
};

TEST(Fire, FindsTheMinimumOfAnAnisotropicQuadratic) {
  Springs springs(20);
  std::vector<Vec3> x(20, Vec3::Zero());
  minimise::FireSettings settings;
  settings.force_tolerance = 1e-9;
  const auto result = minimise::minimise_fire(springs, x, settings);
  ASSERT_TRUE(result.converged);
  for (std::size_t i = 0; i < x.size(); ++i) {
    // |force| < 1e-9 with stiffness >= 1 puts every point within 1e-9 of its target.
    EXPECT_LT((x[i] - springs.targets[i]).norm(), 1e-9) << i;
  }
}

TEST(Fire, StiffnessEstimateApproachesTheLargestEigenvalueFromBelow) {
  Springs springs(20);
  const std::vector<Vec3> x(20, Vec3::Zero());
  // The Jacobian is diagonal with entries -k_i, lambda_max = 100 and the next 94.8: after 30
  // power iterations the next mode's share of the direction is ~0.948^30 = 0.2 of its start, so
  // the estimate |J v| / |v| lies just below 100 (never above: J is symmetric); within 1 % is all
  // a time step needs.
  const double estimate = springs.stiffest_mode(x);
  EXPECT_LE(estimate, 100.0 * (1.0 + 1e-9));
  EXPECT_GT(estimate, 99.0);
}

// The same springs, all of equal stiffness, with sum_i |x_i|^2 held at R^2: the minimum is the
// target scaled onto the sphere, x = R t / |t|.
class SpringsOnASphere : public Springs {
 public:
  SpringsOnASphere(std::size_t count, double radius)
      : Springs(count),
        constraints({{"squared norm",
                      [](std::span<const Vec3> x, std::span<Vec3> gradient) {
                        for (std::size_t i = 0; i < x.size(); ++i) gradient[i] = 2.0 * x[i];
                        return minimise::dot(x, x);
                      },
                      radius * radius, 1e-12}},
                    count) {
    for (auto& k : stiffness) k = 1.0;
  }
  void forces(std::span<const Vec3> x, std::span<Vec3> f) override {
    Springs::forces(x, f);
    constraints.project(x, f);
  }
  void project(std::span<const Vec3> x, std::span<Vec3> v) override { constraints.project(x, v); }
  void restore(std::span<Vec3> x) override { constraints.restore(x); }
  minimise::ConstraintSet constraints;
};

TEST(Fire, HeldConstraintsGiveTheConstrainedMinimum) {
  constexpr double kRadius = 0.5;
  SpringsOnASphere problem(12, kRadius);
  std::vector<Vec3> x(12, Vec3(0.1, 0.0, 0.0));
  problem.restore(x);
  minimise::FireSettings settings;
  settings.force_tolerance = 1e-10;
  const auto result = minimise::minimise_fire(problem, x, settings);
  ASSERT_TRUE(result.converged);
  const double target_norm = minimise::norm(problem.targets);
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_LT((x[i] - kRadius * problem.targets[i] / target_norm).norm(), 1e-8) << i;
  }
  EXPECT_NEAR(minimise::dot(x, x), kRadius * kRadius, 1e-12);
}

// One point held by a spring at x = 0.9 (stiffness 100), with a wall at x = 0.95 where the force
// law is singular (it throws, as the membrane's tau limits do): started far away, FIRE's inertia
// carries the point past the wall, a step it must undo.
class Barrier : public minimise::FireProblem {
 public:
  void forces(std::span<const Vec3> x, std::span<Vec3> f) override {
    if (x[0].x() >= 0.95) throw rbcsim::RuntimeFailure("barrier reached");
    f[0] = Vec3(-(x[0].x() - 0.9) * 100.0, -x[0].y(), -x[0].z());
  }
  double stiffest_mode(std::span<const Vec3>) override { return 100.0; }
};

TEST(Fire, RetreatsFromASingularLimitAndStillConverges) {
  Barrier barrier;
  // Started far away, FIRE's speed-up carries the point past 0.95 before it settles at 0.9.
  std::vector<Vec3> x = {Vec3(-20.0, 0.0, 0.0)};
  minimise::FireSettings settings;
  settings.force_tolerance = 1e-8;
  const auto result = minimise::minimise_fire(barrier, x, settings);
  EXPECT_TRUE(result.converged);
  EXPECT_GT(result.retreats, 0u);
  EXPECT_NEAR(x[0].x(), 0.9, 1e-9);
}

TEST(ConstraintSet, ProjectionIsOrthogonalAndRestorationReachesTheTargets) {
  // Two constraints on three points: the sum of x-coordinates and the squared norm.
  minimise::ConstraintSet constraints({{"x sum",
                                        [](std::span<const Vec3> x, std::span<Vec3> g) {
                                          double sum = 0.0;
                                          for (std::size_t i = 0; i < x.size(); ++i) {
                                            sum += x[i].x();
                                            g[i] = Vec3(1.0, 0.0, 0.0);
                                          }
                                          return sum;
                                        },
                                        1.0, 1e-13},
                                       {"squared norm",
                                        [](std::span<const Vec3> x, std::span<Vec3> g) {
                                          for (std::size_t i = 0; i < x.size(); ++i)
                                            g[i] = 2.0 * x[i];
                                          return minimise::dot(x, x);
                                        },
                                        2.0, 1e-13}},
                                      3);
  std::vector<Vec3> x = {Vec3(0.3, 0.2, 0.1), Vec3(-0.5, 0.4, 0.9), Vec3(0.7, -0.6, 0.2)};
  constraints.restore(x);
  for (double residual : constraints.residuals(x)) EXPECT_LT(std::abs(residual), 1e-13);
  std::vector<Vec3> v = {Vec3(1.0, 2.0, 3.0), Vec3(-1.0, 0.5, 0.0), Vec3(0.2, 0.2, -2.0)};
  constraints.project(x, v);
  double along_sum = 0.0;
  for (const auto& vi : v) along_sum += vi.x();
  EXPECT_NEAR(along_sum, 0.0, 1e-13);
  EXPECT_NEAR(minimise::dot(x, v), 0.0, 1e-13);
}

}  // namespace
