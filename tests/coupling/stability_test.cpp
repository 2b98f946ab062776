// Loud failures (docs/physics.md, "Failures"): each instability stops the run with a RuntimeFailure
// (exit code 1) naming the step and the cell, after a dump for diagnosis; and the checks
// themselves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "coupling/coupled_simulation.hpp"
#include "coupling/stability.hpp"
#include "coupling_fixtures.hpp"
#include "support/files.hpp"
#include "support/scratch_directory.hpp"

namespace rbcsim::coupling {
namespace {

using rbcsim::testing::read_json;
using testing::capsule_parameters;
using testing::couette_fluid;
using testing::periodic_fluid;
using testing::plasma_units;
using testing::sphere_mesh;
using testing::stretched;

// Runs until the simulation throws; returns the message (empty if it never failed).
std::string failure_of(CoupledSimulation& simulation, int max_steps) {
  try {
    for (int step = 0; step < max_steps; ++step) simulation.step();
  } catch (const RuntimeFailure& failure) {
    return failure.what();
  }
  return {};
}

TEST(Instability, HugeExternalForceStopsTheRunWithStepCellAndDump) {
  const rbcsim::testing::ScratchDirectory scratch;
  CouplingParameters parameters;
  parameters.run_directory = scratch.path();
  CoupledSimulation simulation(periodic_fluid(12, 12, 12), plasma_units(), parameters);
  const auto sphere = sphere_mesh(2, 1.5, Vec3(3.0, 3.0, 3.0));
  simulation.add_cell(membrane::MembraneModel(sphere, membrane::MembraneParameters{}),
                      sphere.positions_um);
  // 1 uN on one vertex: it moves several lattice spacings in the first step.
  simulation.add_external_force([](std::size_t, const Cell&, std::span<Vec3> forces_pN) {
    forces_pN[7] += Vec3(1e6, 0.0, 0.0);
  });
  const std::string message = failure_of(simulation, 5);
  const auto dump = scratch.path() / "failure";
  EXPECT_EQ(message.rfind("step 1, cell 0: vertex 7 moved", 0), 0u) << message;
  EXPECT_NE(message.find("stability.max_vertex_step_dx"), std::string::npos);
  EXPECT_NE(message.find("dump written to " + dump.string()), std::string::npos) << message;
  const auto failure = read_json(dump / "failure.json");
  EXPECT_EQ(failure["step"], 1);
  EXPECT_EQ(failure["cell"], 0);
  EXPECT_EQ(failure["reason"].get<std::string>().rfind("vertex 7 moved", 0), 0u);
  EXPECT_EQ(failure["files"], (nlohmann::json{"cell0.vtp", "fluid.vti"}));
  EXPECT_TRUE(std::filesystem::is_regular_file(dump / "cell0.vtp"));
  EXPECT_TRUE(std::filesystem::is_regular_file(dump / "fluid.vti"));
}

// A capsule of 10^7 kBT stretched by 10 % at constant volume: forces of ~10^5 pN per vertex.
CoupledSimulation absurdly_stiff_capsule(double vertex_force_cap_pN) {
  CoupledSimulation simulation(periodic_fluid(12, 12, 12), plasma_units(), {});
  const Vec3 centre_um(3.0, 3.0, 3.0);
  const auto sphere = sphere_mesh(2, 1.5, centre_um);
  auto parameters = capsule_parameters(1e7);
  parameters.vertex_force_cap_pN = vertex_force_cap_pN;
  simulation.add_cell(membrane::MembraneModel(sphere, parameters),
                      stretched(sphere, centre_um, Vec3(1.1, 1.0 / 1.1, 1.0)));
  return simulation;
}

TEST(Instability, AbsurdlyStiffMembraneIsHeldByTheForceCapUntilItTriggersTooLong) {
  auto simulation = absurdly_stiff_capsule(50.0);
  const std::string message = failure_of(simulation, 200);
  // Every vertex is capped from the first step: more than force_cap_max_steps (100) in a row.
  EXPECT_EQ(message.rfind("step 101, cell 0: the vertex force cap (50 pN) clamped more than 1 % "
                          "of the vertices for 101 consecutive steps",
                          0),
            0u)
      << message;
  EXPECT_NE(message.find("no dump (no run directory)"), std::string::npos) << message;
}

TEST(Instability, AbsurdlyStiffMembraneWithoutCapOvershootsInOneStep) {
  auto simulation = absurdly_stiff_capsule(std::numeric_limits<double>::infinity());
  const std::string message = failure_of(simulation, 1);
  EXPECT_EQ(message.rfind("step 1, cell 0: vertex ", 0), 0u) << message;
  EXPECT_NE(message.find(" dx in one step"), std::string::npos) << message;
}

TEST(Instability, NonFiniteFluidStopsTheRunNamingTheFluid) {
  auto fluid = periodic_fluid(12, 12, 12);
  const std::size_t node_count = fluid->grid().node_count();
  lattice::VectorField velocity{std::vector<double>(node_count, 0.0),
                                std::vector<double>(node_count, 0.0),
                                std::vector<double>(node_count, 0.0)};
  velocity[0][fluid->grid().index(10, 10, 10)] = std::numeric_limits<double>::quiet_NaN();
  fluid->initialise_equilibrium(std::vector<double>(node_count, 1.0), velocity);
  CouplingParameters parameters;
  parameters.stability.fluid_check_interval_steps = 3;
  CoupledSimulation simulation(std::move(fluid), plasma_units(), parameters);
  const auto sphere = sphere_mesh(1, 1.0, Vec3(1.5, 1.5, 1.5));
  simulation.add_cell(membrane::MembraneModel(sphere, membrane::MembraneParameters{}),
                      sphere.positions_um);
  const std::string message = failure_of(simulation, 3);
  EXPECT_EQ(message.rfind("step 3, fluid: lattice: non-finite fluid velocity", 0), 0u) << message;
}

TEST(Instability, VertexPushedIntoAWallStopsTheRun) {
  // The lowest vertex starts 0.9 dx above the wall plane y = 1/2; 3e5 pN move it about 1.7 dx in
  // one step, into the wall node layer. The displacement limit is lifted so that this check,
  // not that one, sees it.
  CouplingParameters parameters;
  parameters.stability.max_vertex_step_lu = 100.0;
  CoupledSimulation simulation(couette_fluid(12, 12, 12, 0.0), plasma_units(), parameters);
  const auto sphere = sphere_mesh(2, 1.2, Vec3(3.0, 1.9, 3.0));
  simulation.add_cell(membrane::MembraneModel(sphere, capsule_parameters(100.0)),
                      sphere.positions_um);
  const auto lowest = static_cast<std::size_t>(
      std::ranges::min_element(sphere.positions_um, {}, [](const Vec3& p) { return p.y(); }) -
      sphere.positions_um.begin());
  simulation.add_external_force([lowest](std::size_t, const Cell&, std::span<Vec3> forces_pN) {
    forces_pN[lowest] += Vec3(0.0, -3e5, 0.0);
  });
  const std::string message = failure_of(simulation, 1);
  EXPECT_EQ(message.rfind("step 1, cell 0: vertex ", 0), 0u) << message;
  EXPECT_NE(message.find("entered the non-fluid node ("), std::string::npos) << message;
}

TEST(Instability, CellThatDoesNotFitTheDomainIsBadInput) {
  CoupledSimulation simulation(couette_fluid(12, 12, 12, 0.0), plasma_units(), {});
  // Centred on the wall plane y = 0.
  const auto sphere = sphere_mesh(1, 1.0, Vec3(3.0, 0.0, 3.0));
  try {
    simulation.add_cell(membrane::MembraneModel(sphere, membrane::MembraneParameters{}),
                        sphere.positions_um);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("cell 0: vertex ", 0), 0u) << error.what();
    EXPECT_NE(std::string(error.what()).find("does not fit the domain"), std::string::npos);
  }
}

TEST(Instability, UnderLeesEdwardsACellMayNotReachTheSlidingPlane) {
  // The images above and below slide, so y is not periodic for the IBM: a cell across y = 0 does
  // not fit, one inside does.
  lattice::FluidParameters sliding;
  sliding.lees_edwards_velocity = 0.01;
  CoupledSimulation simulation(
      std::make_unique<lattice::FluidSolver>(lattice::LatticeGrid(12, 12, 12), sliding),
      plasma_units(), {});
  EXPECT_FALSE(simulation.grid_view().periodic_y);
  EXPECT_TRUE(simulation.grid_view().periodic_x && simulation.grid_view().periodic_z);
  const auto across = sphere_mesh(1, 1.0, Vec3(3.0, 0.2, 3.0));
  EXPECT_THROW(simulation.add_cell(membrane::MembraneModel(across, membrane::MembraneParameters{}),
                                   across.positions_um),
               InputError);
  const auto inside = sphere_mesh(1, 1.0, Vec3(3.0, 3.0, 3.0));
  EXPECT_EQ(simulation.add_cell(membrane::MembraneModel(inside, membrane::MembraneParameters{}),
                                inside.positions_um),
            0u);
  simulation.step();
}

TEST(StabilityChecks, VertexMotionProblems) {
  const std::vector<Vec3> previous = {Vec3(1, 1, 1), Vec3(2, 2, 2)};
  const std::vector<Vec3> slow = {Vec3(0.1, 0, 0), Vec3(0, 0.1, 0)};
  std::vector<Vec3> moved = {Vec3(1.1, 1, 1), Vec3(2, 2.1, 2)};
  EXPECT_FALSE(find_vertex_motion_problem(previous, moved, slow, 0.5));
  moved[1] = Vec3(2, 2.6, 2);
  EXPECT_EQ(
      find_vertex_motion_problem(previous, moved, slow, 0.5).value().rfind("vertex 1 moved 0.6", 0),
      0u);
  std::vector<Vec3> nan_velocity = slow;
  nan_velocity[0].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(find_vertex_motion_problem(previous, moved, nan_velocity, 0.5).value(),
            "vertex 0: non-finite fluid velocity interpolated (the flow is unstable)");
}

// The one-pass screen in front of the exact loop must not change a verdict at the limit's edge.
TEST(StabilityChecks, VertexMotionAtTheLimitAndNonFinitePositions) {
  const std::vector<Vec3> previous = {Vec3(1, 1, 1), Vec3(2, 2, 2)};
  const std::vector<Vec3> slow = {Vec3(0.1, 0, 0), Vec3(0, 0.1, 0)};
  const std::vector<Vec3> at_limit = {Vec3(1, 1, 1), Vec3(2.5, 2, 2)};
  EXPECT_FALSE(find_vertex_motion_problem(previous, at_limit, slow, 0.5));
  const std::vector<Vec3> beyond = {Vec3(1, 1, 1), Vec3(std::nextafter(2.5, 3.0), 2, 2)};
  EXPECT_TRUE(find_vertex_motion_problem(previous, beyond, slow, 0.5));
  const std::vector<Vec3> infinite = {Vec3(1, 1, std::numeric_limits<double>::infinity()),
                                      Vec3(2, 2, 2)};
  EXPECT_EQ(find_vertex_motion_problem(previous, infinite, slow, 0.5).value(),
            "vertex 0: non-finite position");
}

// A vertex half-way between two nodes belongs to the one farther from zero (std::lround's rule).
TEST(StabilityChecks, NearestNodeRoundsHalvesAwayFromZero) {
  const ibm::GridView grid{4, 4, 4, true, false, true};
  std::vector<std::uint8_t> mask(64, 0);
  mask[ibm::node_index(grid, 3, 1, 1)] = 1;
  EXPECT_TRUE(find_domain_exit(std::vector<Vec3>{Vec3(-0.5, 1.0, 1.0)}, grid, mask.data()));
  EXPECT_TRUE(find_domain_exit(std::vector<Vec3>{Vec3(2.5, 1.0, 1.0)}, grid, mask.data()));
  EXPECT_FALSE(find_domain_exit(std::vector<Vec3>{Vec3(2.4999, 1.0, 1.0)}, grid, mask.data()));
  EXPECT_FALSE(find_domain_exit(std::vector<Vec3>{Vec3(-0.4999, 1.0, 1.0)}, grid, mask.data()));
  EXPECT_EQ(
      find_domain_exit(std::vector<Vec3>{Vec3(std::nan(""), 1.0, 1.0)}, grid, mask.data()).value(),
      "vertex 0: non-finite position");
}

TEST(StabilityChecks, DomainExitAlongNonPeriodicAxesAndIntoSolidNodes) {
  const ibm::GridView grid{4, 4, 4, true, false, true};
  std::vector<std::uint8_t> mask(64, 0);
  // Periodic x: far outside is fine; non-periodic y: only 0 <= y <= 3.
  EXPECT_FALSE(find_domain_exit(std::vector<Vec3>{Vec3(-7.2, 0.0, 9.4)}, grid, mask.data()));
  EXPECT_EQ(
      find_domain_exit(std::vector<Vec3>{Vec3(1, 1, 1), Vec3(1.0, 3.2, 1.0)}, grid, mask.data())
          .value(),
      "vertex 1 left the domain along y (at 3.2 dx; nodes 0 to 3)");
  // The nearest node of (5.4, 1.6, 2.4) is (1, 2, 2) after wrapping x.
  mask[ibm::node_index(grid, 1, 2, 2)] = 1;
  EXPECT_EQ(find_domain_exit(std::vector<Vec3>{Vec3(5.4, 1.6, 2.4)}, grid, mask.data()).value(),
            "vertex 0 entered the non-fluid node (1, 2, 2): it crossed a wall, inlet or outlet");
  EXPECT_FALSE(find_domain_exit(std::vector<Vec3>{Vec3(5.4, 1.6, 2.4)}, grid, nullptr));
}

TEST(StabilityChecks, ForceCapMustTriggerOnTooManyVerticesForTooManyStepsInARow) {
  StabilityLimits limits;
  limits.force_cap_vertex_fraction = 0.1;
  limits.force_cap_max_steps = 3;
  ForceCapMonitor monitor;
  // 10 of 100 vertices is not more than 10 %: never a capped step, but counted as capping.
  for (int step = 0; step < 10; ++step) EXPECT_FALSE(monitor.record(10, 100, 50.0, limits));
  EXPECT_EQ(monitor.steps_with_capping(), 10u);
  for (int step = 0; step < 3; ++step) EXPECT_FALSE(monitor.record(11, 100, 50.0, limits));
  EXPECT_FALSE(monitor.record(0, 100, 50.0, limits));  // the streak is broken
  for (int step = 0; step < 3; ++step) EXPECT_FALSE(monitor.record(11, 100, 50.0, limits));
  const auto problem = monitor.record(11, 100, 50.0, limits);
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->rfind("the vertex force cap (50 pN) clamped more than 10 % of the vertices "
                           "for 4 consecutive steps",
                           0),
            0u)
      << *problem;
}

}  // namespace
}  // namespace rbcsim::coupling
