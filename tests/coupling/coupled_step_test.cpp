// The coupled step as a whole: momentum handed to the fluid is exactly the vertices' force, a cell
// at rest stays at rest, a uniform flow carries a cell at its own speed, and results do not depend
// on the thread count.
#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <vector>

#include "common/thread_count_scope.hpp"
#include "coupling/coupled_simulation.hpp"
#include "coupling_fixtures.hpp"

namespace rbcsim::coupling {
namespace {

using testing::couette_fluid;
using testing::lees_edwards_fluid;
using testing::periodic_fluid;
using testing::plasma_units;
using testing::sphere_mesh;
using testing::stretched;

// Sum over nodes of the force density the simulation's next step will use (lattice units).
Vec3 total_spread_force_lu(const CoupledSimulation& simulation) {
  const auto& density = simulation.fluid().force_density();
  Vec3 total = Vec3::Zero();
  for (std::size_t node = 0; node < density[0].size(); ++node) {
    total += Vec3(density[0][node], density[1][node], density[2][node]);
  }
  return total;
}

// Sum of the vertex forces and of their magnitudes (the scale of the round-off), lattice units.
std::pair<Vec3, double> total_vertex_force_lu(const CoupledSimulation& simulation) {
  const double lattice_per_pN = simulation.units().to_lattice(units::PhysicalUnit::force_pN, 1.0);
  Vec3 total = Vec3::Zero();
  double magnitude = 0.0;
  for (const Cell& cell : simulation.cells()) {
    for (const Vec3& force : cell.total_forces_pN()) {
      total += lattice_per_pN * force;
      magnitude += lattice_per_pN * force.norm();
    }
  }
  return {total, magnitude};
}

void expect_spread_total_equals_vertex_total(const CoupledSimulation& simulation) {
  const auto [vertex_total, magnitude] = total_vertex_force_lu(simulation);
  ASSERT_GT(magnitude, 0.0);
  // Every vertex's weights sum to 1 after renormalisation, so the totals agree to round-off.
  EXPECT_LT((total_spread_force_lu(simulation) - vertex_total).norm(), 1e-13 * magnitude);
}

TEST(CoupledStep, SpreadForceTotalEqualsVertexForceTotal) {
  const Vec3 centre_um(3.7, 4.1, 3.3);  // off the nodes, so every weight is fractional
  const auto sphere = sphere_mesh(2, 2.0, centre_um);
  CoupledSimulation simulation(periodic_fluid(16, 16, 16), plasma_units(), {});
  simulation.add_cell(membrane::MembraneModel(sphere, membrane::MembraneParameters{}),
                      stretched(sphere, centre_um, Vec3(1.15, 0.95, 0.9)));
  // An external force makes the total non-zero (the membrane's own forces sum to zero).
  simulation.add_external_force([](std::size_t, const Cell&, std::span<Vec3> forces_pN) {
    forces_pN[0] += Vec3(12.0, -3.0, 5.0);
  });
  simulation.spread_forces();
  expect_spread_total_equals_vertex_total(simulation);
}

TEST(CoupledStep, SpreadForceTotalIsExactNextToAWallToo) {
  // phi4 reaches two nodes away: the lowest vertices (y ~ 1.3 dx) have wall nodes (y = 0) in
  // their support, whose weights are dropped and the rest renormalised.
  const Vec3 centre_um(4.1, 2.65, 4.0);
  const auto sphere = sphere_mesh(2, 2.0, centre_um);
  CouplingParameters parameters;
  parameters.kernel = "phi4";
  CoupledSimulation simulation(couette_fluid(16, 16, 16, 0.0), plasma_units(), parameters);
  simulation.add_cell(membrane::MembraneModel(sphere, membrane::MembraneParameters{}),
                      stretched(sphere, centre_um, Vec3(1.1, 1.0, 0.95)));
  simulation.add_external_force([](std::size_t, const Cell&, std::span<Vec3> forces_pN) {
    for (Vec3& force : forces_pN) force += Vec3(0.0, -0.5, 0.0);
  });
  simulation.spread_forces();
  expect_spread_total_equals_vertex_total(simulation);
  // And the step that follows uses these forces rather than spreading again.
  simulation.step();
  EXPECT_EQ(simulation.time_step(), 1u);
}

TEST(CoupledStep, CellAtRestInFluidAtRestStaysAtRest) {
  // Straddling the periodic face x = 0, so the wrapped stencils are exercised too.
  const Vec3 centre_um(0.1, 3.05, 2.93);
  const auto sphere = sphere_mesh(2, 1.5, centre_um);
  CoupledSimulation simulation(periodic_fluid(12, 12, 12), plasma_units(), {});
  simulation.add_cell(membrane::MembraneModel(sphere, membrane::MembraneParameters{}),
                      sphere.positions_um);
  const Cell& cell = simulation.cell(0);
  const Vec3 start_centroid_lu = cell.centroid_lu();
  const std::vector<Vec3> start_lu(cell.positions_lu().begin(), cell.positions_lu().end());
  for (int step = 0; step < 10000; ++step) simulation.step();

  EXPECT_LT((cell.centroid_lu() - start_centroid_lu).norm(), 1e-3);
  const Vec3 drift_lu = cell.centroid_lu() - start_centroid_lu;
  double largest_shape_change_lu = 0.0;
  for (std::size_t v = 0; v < start_lu.size(); ++v) {
    largest_shape_change_lu =
        std::max(largest_shape_change_lu, (cell.positions_lu()[v] - start_lu[v] - drift_lu).norm());
  }
  // The shape is the stress-free reference: only round-off may move it.
  EXPECT_LT(largest_shape_change_lu, 1e-9);
}

TEST(CoupledStep, UniformFlowCarriesAForceFreeCellAtItsSpeed) {
  // Galilean invariance: in a uniform flow a cell at its stress-free shape moves with the flow,
  // so it travels 2 um = 4 dx in 4 / 0.02 = 200 steps.
  const double flow_lu = 0.02;
  auto fluid = periodic_fluid(10, 10, 10);
  fluid->initialise_equilibrium(1.0, {flow_lu, 0.0, 0.0});
  CoupledSimulation simulation(std::move(fluid), plasma_units(), {});
  const auto sphere = sphere_mesh(1, 1.0, Vec3(2.4, 2.6, 2.2));
  simulation.add_cell(membrane::MembraneModel(sphere, membrane::MembraneParameters{}),
                      sphere.positions_um);
  simulation.add_stop_criterion(stop_after_distance(simulation, 0, 2.0));
  const auto summary = simulation.run();
  EXPECT_GE(summary.steps, 200u);
  EXPECT_LE(summary.steps, 201u);  // 200 * 0.02 may round to just below 4
  EXPECT_EQ(summary.stop_reason, "cell 0 travelled 2 um");
  for (const Vec3& velocity : simulation.cell(0).velocities_lu()) {
    EXPECT_NEAR((velocity - Vec3(flow_lu, 0.0, 0.0)).norm(), 0.0, 1e-12);
  }
}

// Everything the coupled loop advances: the vertex positions and the fluid's populations and
// velocity.
struct CoupledState {
  std::vector<Vec3> positions_lu;
  std::vector<double> populations;
  lattice::VectorField velocity;
};

// A deformed capsule relaxing in shear (Couette flow between moving walls, or Lees-Edwards
// images), on more than 4096 nodes so that the lattice really splits its work between threads.
// 41 steps: the optimised fluid kernel ends in its swapped (AA) layout.
template <typename MakeFluid>
CoupledState sheared_capsule_after_steps(int threads, MakeFluid make_fluid,
                                         const membrane::MembraneParameters& membrane) {
  const ThreadCountScope thread_count(threads);
  CouplingParameters parameters;
  parameters.point_advance = "ab2";
  CoupledSimulation simulation(make_fluid(), plasma_units(), parameters);
  const Vec3 centre_um(4.7, 4.3, 3.9);
  const auto sphere = sphere_mesh(2, 2.0, centre_um);
  simulation.add_cell(membrane::MembraneModel(sphere, membrane),
                      stretched(sphere, centre_um, Vec3(1.1, 0.95, 1.0)));
  for (int step = 0; step < 41; ++step) simulation.step();
  const auto positions = simulation.cell(0).positions_lu();
  return {{positions.begin(), positions.end()},
          simulation.fluid().pre_collision_populations(),
          simulation.fluid().velocity()};
}

// The whole coupled step (membrane forces, spreading, LBM sweep, interpolation, point advance)
// with 1 and 2 OpenMP threads, bit for bit.
template <typename MakeFluid>
void expect_thread_independent(MakeFluid make_fluid,
                               const membrane::MembraneParameters& membrane = {}) {
  const auto one = sheared_capsule_after_steps(1, make_fluid, membrane);
  const auto two = sheared_capsule_after_steps(2, make_fluid, membrane);
  ASSERT_EQ(one.positions_lu.size(), two.positions_lu.size());
  for (std::size_t v = 0; v < one.positions_lu.size(); ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      ASSERT_EQ(one.positions_lu[v][axis], two.positions_lu[v][axis]) << "vertex " << v;
    }
  }
  EXPECT_TRUE(one.populations == two.populations);
  for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(one.velocity[axis], two.velocity[axis]);
  // The run did something: the capsule moved.
  const Vec3 centre_um(4.7, 4.3, 3.9);
  const auto start_um = stretched(sphere_mesh(2, 2.0, centre_um), centre_um, Vec3(1.1, 0.95, 1.0));
  EXPECT_GT((one.positions_lu[0] - start_um[0] / 0.5).norm(), 1e-3);
}

TEST(CoupledStep, ResultsAreBitIdenticalForOneAndTwoThreadsBetweenWalls) {
  expect_thread_independent([] { return couette_fluid(20, 18, 16, 0.01); });
}

TEST(CoupledStep, ResultsAreBitIdenticalForOneAndTwoThreadsWithLeesEdwards) {
  expect_thread_independent([] { return lees_edwards_fluid(20, 18, 16, 0.02); });
}

// With membrane viscosity: the implicit friction step (conjugate gradients) too.
TEST(CoupledStep, ResultsAreBitIdenticalForOneAndTwoThreadsWithMembraneViscosity) {
  membrane::MembraneParameters membrane;
  membrane.forces.push_back("viscosity");
  expect_thread_independent([] { return couette_fluid(20, 18, 16, 0.01); }, membrane);
}

// membrane.viscosity_Pa_s_um = 0 with the term switched on: every vertex and every population as
// without the term, bit for bit (issue: "0 reproduces today's results").
TEST(CoupledStep, AMembraneViscosityOfZeroLeavesTheRunBitIdentical) {
  const auto fluid = [] { return couette_fluid(20, 18, 16, 0.01); };
  membrane::MembraneParameters with_zero;
  with_zero.forces.push_back("viscosity");
  with_zero.viscosity_Pa_s_um = 0.0;
  const auto without = sheared_capsule_after_steps(1, fluid, membrane::MembraneParameters{});
  const auto zero = sheared_capsule_after_steps(1, fluid, with_zero);
  for (std::size_t v = 0; v < without.positions_lu.size(); ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      ASSERT_EQ(without.positions_lu[v][axis], zero.positions_lu[v][axis]) << "vertex " << v;
    }
  }
  EXPECT_TRUE(without.populations == zero.populations);
}

}  // namespace
}  // namespace rbcsim::coupling

namespace rbcsim::coupling {
namespace {

// One cell's kernels open top-level parallel regions. Nested in a region over the cells, even an
// inactive one (`if (false)`), each of their regions made GNU OpenMP start threads of its own,
// which competed with the top-level team's spinning workers: a two-thread capillary step took
// 10.4 ms against 1.9 ms on one thread. The external forces run where the membrane kernels do;
// with several cells they run inside the one region over the cells.
TEST(CoupledStep, OneCellsKernelsRunOutsideAnyParallelRegion) {
  const ThreadCountScope threads(2);
  CoupledSimulation simulation(testing::periodic_fluid(16, 16, 16), testing::plasma_units(), {});
  std::vector<int> levels;
  simulation.add_external_force([&levels](std::size_t, const Cell&, std::span<Vec3>) {
#pragma omp critical
    levels.push_back(omp_get_level());
  });
  const auto first = testing::sphere_mesh(2, 1.5, Vec3(4.0, 8.0, 8.0));
  simulation.add_cell(membrane::MembraneModel(first, membrane::MembraneParameters{}),
                      first.positions_um);
  simulation.step();
  EXPECT_EQ(levels, std::vector<int>{0});
  const auto second = testing::sphere_mesh(2, 1.5, Vec3(12.0, 8.0, 8.0));
  simulation.add_cell(membrane::MembraneModel(second, membrane::MembraneParameters{}),
                      second.positions_um);
  levels.clear();
  simulation.step();
  EXPECT_EQ(levels, (std::vector<int>{1, 1}));
}

}  // namespace
}  // namespace rbcsim::coupling
