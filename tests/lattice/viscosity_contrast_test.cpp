// Per-node viscosity (collision.hpp, "viscosity classes"): the class table, and two-layer channel
// flows whose layers differ in viscosity by a factor lambda, against the analytic piecewise
// profiles (continuous velocity and shear stress at the interface). The indicator is sharp and
// aligned to the nodes: the interface lies half-way between the last node of one layer and the
// first of the other.
#include "common/errors.hpp"
#include "flow_helpers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace rbcsim::lattice {
namespace {

using testing::add_channel_walls;
using testing::relative_l2_error_x;

TEST(ViscosityClasses, RatesFollowTheIndicatorLinearlyInViscosity) {
  const CollisionParameters parameters{1.0, 3.0 / 16.0};
  const double ratio = 5.0;
  for (const char* model : {"trt", "bgk"}) {
    const auto rates = viscosity_class_rates(model, parameters, ratio);
    ASSERT_EQ(rates.size(), static_cast<std::size_t>(kViscosityClasses));
    const RelaxationRates outside = relaxation_rates(model, parameters);
    EXPECT_EQ(rates[0].even, outside.even) << model;
    EXPECT_EQ(rates[0].odd, outside.odd) << model;
    for (const int k : {1, 100, 255}) {
      const double indicator = k / 255.0;
      const double tau_even = 1.0 / rates[k].even;
      const double tau_odd = 1.0 / rates[k].odd;
      EXPECT_NEAR(tau_even - 0.5, 0.5 * (1.0 + (ratio - 1.0) * indicator), 1e-12) << model;
      if (std::string(model) == "trt") {
        EXPECT_NEAR((tau_even - 0.5) * (tau_odd - 0.5), 3.0 / 16.0, 1e-14) << k;
      } else {
        EXPECT_EQ(rates[k].odd, rates[k].even) << k;
      }
    }
    // tau+ = 3 inside at lambda = 5 (viscosity.md's example), tau- = 0.575 with TRT.
    EXPECT_NEAR(1.0 / rates[255].even, 3.0, 1e-12);
  }
  EXPECT_NEAR(1.0 / viscosity_class_rates("trt", parameters, ratio)[255].odd, 0.575, 1e-12);
  EXPECT_EQ(viscosity_class(0.0), 0);
  EXPECT_EQ(viscosity_class(1.0), 255);
  EXPECT_EQ(viscosity_class(0.5), 128);
  EXPECT_EQ(viscosity_class(0.4 / 255.0), 0);
}

TEST(ViscosityClasses, RatioMustBePositiveAndFinite) {
  for (const double ratio : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    try {
      viscosity_class_rates("trt", {}, ratio);
      ADD_FAILURE() << ratio;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("physics.cytoplasm_viscosity_ratio"),
                std::string::npos);
    }
  }
  FluidParameters parameters;
  FluidSolver uniform(LatticeGrid(4, 4, 4), parameters);
  EXPECT_FALSE(uniform.has_viscosity_contrast());
  EXPECT_THROW(uniform.viscosity_classes(), std::logic_error);
  parameters.inner_viscosity_ratio = 5.0;
  FluidSolver contrast(LatticeGrid(4, 4, 4), parameters);
  ASSERT_TRUE(contrast.has_viscosity_contrast());
  EXPECT_EQ(contrast.viscosity_classes().size(), 64u);
  EXPECT_EQ(contrast.viscosity(), uniform.viscosity());  // the outer fluid's
}

enum class Drive { couette, poiseuille };

struct TwoLayers {
  int width = 24;        // fluid nodes across, walls half-way at y = 1/2 and width + 1/2
  int lower_nodes = 10;  // nodes y = 1..lower_nodes at viscosity nu, the rest at lambda nu
  double ratio = 5.0;    // lambda
  std::string kernel = "optimised";
  std::string collision = "trt";
  Drive drive = Drive::poiseuille;
};

constexpr double kPeakVelocity = 0.01;

// Lower layer (y_b, y_i) at viscosity nu1, upper (y_i, y_t) at nu2; u = 0 at the walls except the
// top wall's `top` (Couette), body force g (Poiseuille); continuous u and nu du/dy at y_i. In each
// layer u = -g/(2 nu) (y - y_wall)^2 + slope (y - y_wall) (+ top in the upper layer).
struct TwoLayerProfile {
  double y_bottom, y_interface, y_top, nu1, nu2, g, top;
  double lower_slope = 0.0;
  double upper_slope = 0.0;

  void solve() {
    const double h1 = y_interface - y_bottom;
    const double h2 = y_top - y_interface;
    // Stress: -g h1 + nu1 A = g h2 + nu2 B; continuity:
    // -g h1^2/(2 nu1) + A h1 = top - g h2^2/(2 nu2) - B h2.
    lower_slope =
        (top + g * h1 * h1 / (2.0 * nu1) - g * h2 * h2 / (2.0 * nu2) + h2 * g * (h1 + h2) / nu2) /
        (h1 + h2 * nu1 / nu2);
    upper_slope = (nu1 * lower_slope - g * (h1 + h2)) / nu2;
  }
  double operator()(double y) const {
    if (y < y_interface) {
      return -g / (2.0 * nu1) * (y - y_bottom) * (y - y_bottom) + lower_slope * (y - y_bottom);
    }
    return top - g / (2.0 * nu2) * (y - y_top) * (y - y_top) + upper_slope * (y - y_top);
  }
};

double two_layer_error(const TwoLayers& layers) {
  FluidParameters parameters;
  parameters.kernel = layers.kernel;
  parameters.collision = layers.collision;
  parameters.inner_viscosity_ratio = layers.ratio;
  const double nu1 = (parameters.collision_parameters.tau - 0.5) / 3.0;
  TwoLayerProfile profile{
      0.5, layers.lower_nodes + 0.5, layers.width + 0.5, nu1, layers.ratio * nu1, 0.0, 0.0};
  if (layers.drive == Drive::poiseuille) {
    // About kPeakVelocity at the peak whatever the ratio.
    profile.g = 8.0 * std::max(nu1, profile.nu2) * kPeakVelocity / (layers.width * layers.width);
    parameters.body_force = {profile.g, 0.0, 0.0};
  } else {
    profile.top = kPeakVelocity;
  }
  profile.solve();
  FluidSolver solver(LatticeGrid(4, layers.width + 2, 1), parameters);
  add_channel_walls(solver, {profile.top, 0.0, 0.0});
  const LatticeGrid& grid = solver.grid();
  for (std::size_t node = 0; node < grid.node_count(); ++node) {
    if (grid.coordinates(node)[1] > layers.lower_nodes) solver.viscosity_classes()[node] = 255;
  }
  const auto steady = solver.run_to_steady_state({1e-10, 200, 400000});
  EXPECT_TRUE(steady.converged) << steady.relative_velocity_change;
  return relative_l2_error_x(solver, [&](int, int y, int) { return profile(y); });
}

// With TRT at a fixed magic parameter, each layer's linear (Couette) or parabolic (Poiseuille)
// profile is an exact steady solution of the lattice equations, the half-way walls sit exactly
// half-way whatever the local tau, and the stress is continuous half-way between the layers' last
// and first nodes: the two-layer profile is reproduced to the steady-state tolerance. The Guo
// forcing must use each node's own rates for this (a uniform prefactor puts a force jump at the
// interface).
TEST(TwoLayerChannel, TrtReproducesCouetteAndPoiseuilleExactly) {
  for (const char* kernel : {"optimised", "reference"}) {
    for (const Drive drive : {Drive::couette, Drive::poiseuille}) {
      for (const double ratio : {5.0, 0.2}) {
        TwoLayers layers;
        layers.kernel = kernel;
        layers.ratio = ratio;
        layers.drive = drive;
        const double error = two_layer_error(layers);
        std::printf("two-layer %s %s, lambda %.1f, 24 nodes: L2 error %.3e\n",
                    drive == Drive::couette ? "Couette" : "Poiseuille", kernel, ratio, error);
        EXPECT_LT(error, 1e-8) << kernel << " lambda " << ratio;
      }
    }
  }
}

// BGK misplaces half-way walls by a tau-dependent O(dx^2) amount, large in the layer at tau = 3:
// the error is a few percent at 24 nodes and falls at second order (the interface stays at the
// same fraction of the channel).
TEST(TwoLayerChannel, BgkPoiseuilleConvergesAtSecondOrder) {
  TwoLayers coarse;
  coarse.collision = "bgk";
  TwoLayers fine = coarse;
  fine.width = 2 * coarse.width;
  fine.lower_nodes = 2 * coarse.lower_nodes;
  const double coarse_error = two_layer_error(coarse);
  const double fine_error = two_layer_error(fine);
  const double order = std::log2(coarse_error / fine_error);
  std::printf(
      "two-layer Poiseuille BGK, lambda 5: L2 error %.3e (24 nodes), %.3e (48), order %.2f\n",
      coarse_error, fine_error, order);
  EXPECT_LT(coarse_error, 0.04);
  EXPECT_GT(order, 1.8);
}

// The same flow with one viscosity everywhere is far from the two-layer profile: the test can
// tell a missing contrast.
TEST(TwoLayerChannel, WithoutTheContrastTheProfileIsWrong) {
  TwoLayers layers;
  const double with = two_layer_error(layers);
  FluidParameters parameters;
  const double nu = (parameters.collision_parameters.tau - 0.5) / 3.0;
  TwoLayerProfile profile{0.5,
                          layers.lower_nodes + 0.5,
                          layers.width + 0.5,
                          nu,
                          layers.ratio * nu,
                          8.0 * layers.ratio * nu * kPeakVelocity / (layers.width * layers.width),
                          0.0};
  profile.solve();
  parameters.body_force = {profile.g, 0.0, 0.0};
  FluidSolver uniform(LatticeGrid(4, layers.width + 2, 1), parameters);
  add_channel_walls(uniform);
  uniform.run_to_steady_state({1e-10, 200, 400000});
  const double without = relative_l2_error_x(uniform, [&](int, int y, int) { return profile(y); });
  EXPECT_GT(without, 100.0 * with);
}

}  // namespace
}  // namespace rbcsim::lattice
