// Contact between cells in the coupled step (CoupledSimulation::set_cell_contact): two capsules
// pushed into each other stop at the repulsion's range, the contact adds no net force, and the
// result does not depend on the thread count, also with more cells than threads (the step's
// parallel loop over cells), with either law. Cells colliding in shear:
// tests/cli_capillary/cli_suspension_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "cases/suspension_packing.hpp"
#include "common/thread_count_scope.hpp"
#include "coupling_fixtures.hpp"
#include "membrane/membrane_model.hpp"

namespace rbcsim::coupling {
namespace {

using testing::capsule_parameters;
using testing::periodic_fluid;
using testing::plasma_units;
using testing::sphere_mesh;

constexpr double kPushPerVertexPN = 0.5;
const contact::ContactParameters kContact{50.0, 0.75};

// Two capsules of radius 2 um, 642 vertices each (edges about 0.3 um), their surfaces 0.7 um apart
// along x (just inside the range) in a periodic box, each pushed towards the other with 0.5 pN per
// vertex (321 pN). (Starting farther apart, the film between them drains for thousands of steps
// before they meet.)
std::unique_ptr<CoupledSimulation> pushed_pair(
    const contact::ContactParameters& contact = kContact) {
  auto simulation = std::make_unique<CoupledSimulation>(periodic_fluid(36, 20, 20), plasma_units(),
                                                        CouplingParameters{});
  for (const double x_um : {6.5, 11.2}) {
    const auto sphere = sphere_mesh(3, 2.0, Vec3(x_um, 5.0, 5.0));
    simulation->add_cell(membrane::MembraneModel(sphere, capsule_parameters(300.0)),
                         sphere.positions_um);
  }
  simulation->add_external_force([](std::size_t cell, const Cell&, std::span<Vec3> forces_pN) {
    const double direction = cell == 0 ? 1.0 : -1.0;
    for (Vec3& force : forces_pN) force.x() += direction * kPushPerVertexPN;
  });
  simulation->set_cell_contact(contact, "test");
  return simulation;
}

// The sum of both cells' external forces (pushes and contact) and the sum of their magnitudes.
std::pair<Vec3, double> net_external_force(const CoupledSimulation& simulation) {
  Vec3 net = Vec3::Zero();
  double magnitude = 0.0;
  for (std::size_t c = 0; c < 2; ++c) {
    for (const Vec3& force : simulation.cell(c).external_forces_pN()) {
      net += force;
      magnitude += force.norm();
    }
  }
  return {net, magnitude};
}

double closest_vertices_um(const CoupledSimulation& simulation) {
  const auto a = simulation.positions_now_um(0);
  const auto b = simulation.positions_now_um(1);
  double closest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : a) {
    for (const Vec3& q : b) closest = std::min(closest, (p - q).norm());
  }
  return closest;
}

TEST(CellContact, PushedCellsStopAtTheRangeWithoutNetForce) {
  auto simulation = pushed_pair();
  EXPECT_NEAR(closest_vertices_um(*simulation), 0.7, 1e-3);
  // The contact's own measure of the closest pair, each step (infinite while none is in range).
  double closest_um = std::numeric_limits<double>::infinity();
  for (int step = 0; step < 2500; ++step) {
    simulation->step();
    closest_um = std::min(closest_um, simulation->contact_statistics().closest_um);
  }
  EXPECT_NEAR(closest_um, std::min(closest_um, closest_vertices_um(*simulation)), 0.1);
  // They met (within the range) and were held off near it: the push flattens the capsules
  // against each other (their centroids keep approaching) while the surfaces stay about the range
  // apart; none came within a quarter of it, and no vertex of one is inside the other.
  EXPECT_LT(closest_um, kContact.range_um);
  EXPECT_GT(closest_um, 0.5 * kContact.range_um);
  EXPECT_EQ(simulation->close_contact_steps(), 0u);
  const auto b = simulation->positions_now_um(1);
  const auto sphere = sphere_mesh(3, 2.0, Vec3::Zero());
  for (const Vec3& p : simulation->positions_now_um(0)) {
    ASSERT_FALSE(cases::surface_contains(b, sphere.triangles, p));
  }
  // The pushes cancel exactly; the contact forces cancel pair by pair.
  const auto [net, magnitude] = net_external_force(*simulation);
  EXPECT_GT(simulation->contact_statistics().pairs_in_range, 0u);
  EXPECT_LT(net.norm(), 1e-13 * magnitude);
}

TEST(CellContact, OneAndTwoThreadsGiveTheSameRun) {
  std::vector<std::vector<Vec3>> positions;
  for (const int threads : {1, 2}) {
    const ThreadCountScope scope(threads);
    auto simulation = pushed_pair();
    for (int step = 0; step < 800; ++step) simulation->step();
    EXPECT_GT(simulation->contact_statistics().pairs_in_range, 0u);
    positions.push_back(simulation->positions_now_um(1));
  }
  EXPECT_EQ(positions[0], positions[1]);
}

// The surface law (contact/surface_repulsion.hpp) in the coupled step: the capsules' vertices
// meet the other's surface within the range, the pushes and their reactions on the triangles
// cancel to round-off, and one and two threads give the same run.
TEST(CellContact, SurfaceLawInTheCoupledStep) {
  std::vector<std::vector<Vec3>> positions;
  for (const int threads : {1, 2}) {
    const ThreadCountScope scope(threads);
    // A cap of 0.01 pN, reached where the law's (r / d - 1)^2 passes 1/500, at d < 0.718 um,
    // which the pushed cells pass: every step with a capped push is counted.
    auto simulation = pushed_pair({5.0, 0.75, contact::ContactLaw::surface, 0.01});
    for (int step = 0; step < 200; ++step) simulation->step();
    EXPECT_GT(simulation->contact_statistics().pairs_in_range, 0u);
    EXPECT_LT(simulation->contact_statistics().closest_um, 0.71);
    EXPECT_GT(simulation->contact_statistics().capped_pushes, 0u);
    EXPECT_GT(simulation->capped_contact_steps(), 0u);
    const auto [net, magnitude] = net_external_force(*simulation);
    EXPECT_LT(net.norm(), 1e-12 * magnitude);
    positions.push_back(simulation->positions_now_um(1));
  }
  EXPECT_EQ(positions[0], positions[1]);
}

// Seven small capsules in a row along x, alternately above and below y = 5 um, neighbours 0.4 um
// apart (within the range, their stencils sharing nodes), driven alternately along +x and -x,
// after `steps` steps on `threads` threads: the step's loop over cells hands them to the threads in
// a varying order. `viscous`: with membrane viscosity, whose friction solves run in parallel over
// the cells on one fluid state.
std::vector<Vec3> seven_capsules_after(int steps, int threads, bool viscous) {
  const ThreadCountScope scope(threads);
  auto simulation = std::make_unique<CoupledSimulation>(periodic_fluid(48, 20, 16), plasma_units(),
                                                        CouplingParameters{});
  auto parameters = capsule_parameters(300.0);
  if (viscous) parameters.forces.push_back("viscosity");
  for (int c = 0; c < 7; ++c) {
    const auto sphere = sphere_mesh(3, 1.4, Vec3(2.0 + 3.0 * c, 5.0 + (c % 2 ? 0.8 : -0.8), 4.0));
    simulation->add_cell(membrane::MembraneModel(sphere, parameters), sphere.positions_um);
  }
  simulation->add_external_force([](std::size_t cell, const Cell&, std::span<Vec3> forces_pN) {
    const double direction = cell % 2 == 0 ? 1.0 : -1.0;
    for (Vec3& force : forces_pN) force.x() += direction * kPushPerVertexPN;
  });
  simulation->set_cell_contact(kContact, "test");
  for (int step = 0; step < steps; ++step) simulation->step();
  EXPECT_GT(simulation->contact_statistics().pairs_in_range, 0u);
  if (viscous) {
    EXPECT_GT(simulation->cell(3).friction_iterations(), 0u);
  }
  std::vector<Vec3> all;
  for (std::size_t c = 0; c < 7; ++c) {
    const auto cell = simulation->positions_now_um(c);
    all.insert(all.end(), cell.begin(), cell.end());
  }
  return all;
}

TEST(CellContact, MoreCellsThanThreadsGiveTheSameRunOnOneAndTwoThreads) {
  EXPECT_EQ(seven_capsules_after(300, 1, false), seven_capsules_after(300, 2, false));
}

TEST(CellContact, MoreCellsThanThreadsWithMembraneViscosityGiveTheSameRunOnOneAndTwoThreads) {
  // 60 steps: 30 friction solves (every second step with the optimised kernel).
  const auto one = seven_capsules_after(60, 1, true);
  EXPECT_EQ(one, seven_capsules_after(60, 2, true));
  EXPECT_NE(one, seven_capsules_after(60, 1, false));  // the friction acted
}

}  // namespace
}  // namespace rbcsim::coupling
