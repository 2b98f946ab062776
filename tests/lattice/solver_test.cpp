// The driver's guards: loud failures for unstable flow, bad Lees-Edwards geometry, and geometry
// edits after the fluid has started.
#include "lattice/fluid_solver.hpp"

#include "common/errors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace rbcsim::lattice {
namespace {

TEST(FluidSolver, UnstableFlowStopsWithTheStepAndNode) {
  FluidParameters parameters;
  parameters.collision = "bgk";
  parameters.collision_parameters.tau = 0.5001;  // almost inviscid
  FluidSolver solver(LatticeGrid(8, 8, 1), parameters);
  const std::size_t n = solver.grid().node_count();
  VectorField velocity{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
  for (std::size_t node = 0; node < n; ++node) {
    const auto [x, y, z] = solver.grid().coordinates(node);
    velocity[0][node] = 0.6 * std::sin(0.8 * y);  // far above the lattice Mach limit
    velocity[1][node] = 0.6 * std::cos(0.8 * x);
  }
  solver.initialise_equilibrium(std::vector<double>(n, 1.0), velocity);
  try {
    solver.run_to_steady_state({1e-12, 50, 20000});
    FAIL() << "an unstable run must throw";
  } catch (const RuntimeFailure& failure) {
    const std::string message = failure.what();
    EXPECT_NE(message.find("non-finite fluid velocity at node ("), std::string::npos) << message;
    EXPECT_NE(message.find("after step"), std::string::npos) << message;
  }
}

TEST(FluidSolver, SlidingPlanesMustBeFluid) {
  FluidParameters parameters;
  parameters.lees_edwards_velocity = 0.01;
  FluidSolver solver(LatticeGrid(4, 6, 2), parameters);
  solver.set_wall(solver.grid().index(1, 5, 0));
  try {
    solver.step();
    FAIL() << "a wall on a sliding plane must be refused";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("shear.boundary"), std::string::npos);
  }
}

TEST(FluidSolver, GeometryIsFixedOnceStepping) {
  FluidSolver solver(LatticeGrid(4, 4, 4), {});
  solver.set_wall(0);
  solver.step();
  EXPECT_THROW(solver.set_wall(1), std::logic_error);
  EXPECT_THROW(solver.set_pressure_outlet(1, 1.0), std::logic_error);
}

TEST(FluidSolver, NonFluidNodesReportNoDensityAndTheirWallVelocity) {
  FluidSolver solver(LatticeGrid(4, 4, 4), {});
  solver.set_wall(3, {0.01, 0.0, -0.02});
  solver.set_pressure_outlet(5, 1.01);
  EXPECT_EQ(solver.solid_mask()[3], static_cast<std::uint8_t>(NodeKind::wall));
  EXPECT_EQ(solver.solid_mask()[5], static_cast<std::uint8_t>(NodeKind::pressure_outlet));
  EXPECT_EQ(solver.density()[3], 0.0);
  EXPECT_EQ(solver.velocity_at(3), (std::array<double, 3>{0.01, 0.0, -0.02}));
  EXPECT_EQ(solver.velocity_at(5), (std::array<double, 3>{0.0, 0.0, 0.0}));
  EXPECT_EQ(solver.boundaries().fluid_node_count(), 62u);
}

}  // namespace
}  // namespace rbcsim::lattice
