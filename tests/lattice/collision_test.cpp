#include "lattice/collision.hpp"

#include "common/errors.hpp"
#include "lattice/fluid_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace rbcsim::lattice {
namespace {

std::string input_error_message(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(CollisionModels, RegistryListsBgkAndTrt) {
  std::vector<std::string> names;
  for (const auto& model : collision_models()) {
    names.emplace_back(model.name);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"bgk", "trt"}));
}

TEST(CollisionModels, BgkRelaxesBothPartsAtOneOverTau) {
  const auto rates = relaxation_rates("bgk", {0.8, 3.0 / 16.0});
  EXPECT_DOUBLE_EQ(rates.even, 1.0 / 0.8);
  EXPECT_DOUBLE_EQ(rates.odd, 1.0 / 0.8);
}

TEST(CollisionModels, TrtOddRateFollowsTheMagicParameter) {
  const double tau = 0.9;
  const double magic = 3.0 / 16.0;
  const auto rates = relaxation_rates("trt", {tau, magic});
  EXPECT_DOUBLE_EQ(rates.even, 1.0 / tau);
  EXPECT_NEAR((tau - 0.5) * (1.0 / rates.odd - 0.5), magic, 1e-15);
}

TEST(CollisionModels, BadInputNamesTheKey) {
  EXPECT_NE(input_error_message([] { relaxation_rates("mrt", {}); }).find("lattice.collision"),
            std::string::npos);
  EXPECT_NE(input_error_message([] { relaxation_rates("mrt", {}); }).find("bgk, trt"),
            std::string::npos);
  EXPECT_NE(input_error_message([] {
              relaxation_rates("bgk", {0.5, 0.1});
            }).find("lattice.relaxation_time"),
            std::string::npos);
  EXPECT_NE(input_error_message([] {
              relaxation_rates("trt", {1.0, 0.0});
            }).find("lattice.trt_magic"),
            std::string::npos);
  FluidParameters parameters;
  parameters.kernel = "fastest";
  EXPECT_NE(input_error_message([&] {
              FluidSolver solver(LatticeGrid(2, 2, 2), parameters);
            }).find("lattice.kernel"),
            std::string::npos);
}

// Guo forcing adds exactly F to the momentum per step, and the velocity of a step carries half of
// that step's force: after n steps from rest, u = (n - 1/2) F / rho. Field and body force add up.
// Tolerance: round-off of the momentum sums over 19 populations of order 0.1, for 11 steps.
TEST(GuoForcing, UniformForceAcceleratesAtExactlyFOverRho) {
  for (const char* kernel : {"reference", "optimised"}) {
    FluidParameters parameters;
    parameters.kernel = kernel;
    parameters.body_force = {1e-5, 0.0, -2e-5};
    FluidSolver solver(LatticeGrid(4, 3, 5), parameters);
    const std::size_t steps = 11;
    for (std::size_t s = 0; s < steps; ++s) {
      auto& force = solver.force_density();
      std::fill(force[1].begin(), force[1].end(), 3e-5);
      solver.step();
    }
    const double factor = steps - 0.5;
    for (std::size_t node = 0; node < solver.grid().node_count(); ++node) {
      EXPECT_NEAR(solver.density()[node], 1.0, 1e-14);
      EXPECT_NEAR(solver.velocity()[0][node], factor * 1e-5, 2e-15) << kernel;
      EXPECT_NEAR(solver.velocity()[1][node], factor * 3e-5, 2e-15) << kernel;
      EXPECT_NEAR(solver.velocity()[2][node], factor * -2e-5, 2e-15) << kernel;
    }
    for (const auto& component : solver.force_density()) {
      for (const double value : component) {
        EXPECT_EQ(value, 0.0);
      }
    }
  }
}

// TRT with Lambda = (tau - 1/2)^2 has tau_odd = tau: it is BGK, up to the order of operations.
TEST(CollisionModels, TrtWithEqualRatesReproducesBgk) {
  const double tau = 0.7;
  const auto shear_wave = [&](const std::string& model, double magic) {
    FluidParameters parameters;
    parameters.collision = model;
    parameters.collision_parameters = {tau, magic};
    FluidSolver solver(LatticeGrid(16, 8, 3), parameters);
    const std::size_t n = solver.grid().node_count();
    VectorField velocity{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
    for (std::size_t node = 0; node < n; ++node) {
      const auto [x, y, z] = solver.grid().coordinates(node);
      velocity[0][node] = 0.02 * std::sin(2.0 * std::numbers::pi * y / 8.0);
      velocity[1][node] = 0.01 * std::cos(2.0 * std::numbers::pi * (x + z) / 16.0);
    }
    solver.initialise_equilibrium(std::vector<double>(n, 1.0), velocity);
    solver.advance(40);
    return solver.pre_collision_populations();
  };
  const auto bgk = shear_wave("bgk", 3.0 / 16.0);
  const auto trt = shear_wave("trt", (tau - 0.5) * (tau - 0.5));
  ASSERT_EQ(bgk.size(), trt.size());
  for (std::size_t k = 0; k < bgk.size(); ++k) {
    ASSERT_NEAR(bgk[k], trt[k], 1e-15);
  }
}

}  // namespace
}  // namespace rbcsim::lattice
