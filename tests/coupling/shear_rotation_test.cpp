// A stiff spherical capsule in simple shear rotates like a rigid sphere: with angular velocity
// half the shear rate, against the vorticity (Jeffery 1922; for a capsule without viscosity
// contrast, the tank-treading frequency of a sphere). The whole coupled loop takes part: membrane
// forces, spreading, moving walls, interpolation, advance.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/coupled_simulation.hpp"
#include "coupling_fixtures.hpp"

namespace rbcsim::coupling {
namespace {

using testing::capsule_parameters;
using testing::couette_fluid;
using testing::plasma_units;
using testing::sphere_mesh;

// Angular velocity about z of the vertices around their centroid (least squares for a rigid
// rotation in the x-y plane): sum (r x v)_z / sum |r_xy|^2, lattice units.
// The velocities were sampled at positions_um() (origin at node 0, dx = 0.5 um).
double angular_velocity_z(const Cell& cell) {
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& position_um : cell.positions_um()) centroid += position_um / 0.5;
  centroid /= static_cast<double>(cell.vertex_count());
  double moment = 0.0;
  double inertia = 0.0;
  for (std::size_t v = 0; v < cell.vertex_count(); ++v) {
    const Vec3 r = cell.positions_um()[v] / 0.5 - centroid;
    const Vec3& u = cell.velocities_lu()[v];
    moment += r.x() * u.y() - r.y() * u.x();
    inertia += r.x() * r.x() + r.y() * r.y();
  }
  return moment / inertia;
}

// The capsule's mean angular velocity over steps 1500-2000, in units of the rigid sphere's
// -shear_rate / 2.
double rotation_over_jeffery(const membrane::MembraneParameters& parameters) {
  // Gap of 32 fluid nodes between walls moving at -U and +U: shear rate 2 U / 32. Capsule radius
  // 4.5 dx (642 vertices, edges ~0.6 dx), so the confinement 2R/H is 0.28.
  const int nx = 32, ny = 34, nz = 24;
  const double wall_speed = 0.002;
  const double gap = ny - 2.0;
  const double shear_rate = 2.0 * wall_speed / gap;
  auto fluid = couette_fluid(nx, ny, nz, wall_speed);
  // Start from the linear profile (walls half-way at y = 1/2 and y = ny - 3/2) so that only the
  // disturbance of the capsule has to develop.
  const std::size_t node_count = fluid->grid().node_count();
  lattice::VectorField velocity{std::vector<double>(node_count, 0.0),
                                std::vector<double>(node_count, 0.0),
                                std::vector<double>(node_count, 0.0)};
  for (std::size_t node = 0; node < node_count; ++node) {
    const int y = fluid->grid().coordinates(node)[1];
    velocity[0][node] = -wall_speed + shear_rate * (y - 0.5);
  }
  fluid->initialise_equilibrium(std::vector<double>(node_count, 1.0), velocity);

  CoupledSimulation simulation(std::move(fluid), plasma_units(), {});
  const double dx_um = 0.5;
  const Vec3 centre_um = dx_um * Vec3(0.5 * (nx - 1), 0.5 * (ny - 1), 0.5 * (nz - 1));
  const auto sphere = sphere_mesh(3, 4.5 * dx_um, centre_um);
  simulation.add_cell(membrane::MembraneModel(sphere, parameters), sphere.positions_um);
  for (int step = 0; step < 1500; ++step) simulation.step();
  double mean_angular_velocity = 0.0;
  const int samples = 10;
  for (int sample = 0; sample < samples; ++sample) {
    for (int step = 0; step < 50; ++step) simulation.step();
    mean_angular_velocity += angular_velocity_z(simulation.cell(0)) / samples;
  }
  // Flow along +x increasing with y: vorticity -shear_rate along z, rotation -shear_rate / 2.
  return mean_angular_velocity / (-0.5 * shear_rate);
}

TEST(ShearRotation, StiffSphericalCapsuleRotatesAtHalfTheShearRate) {
  // Capillary number mu shear_rate R / G ~ 1e-3 at 700 kBT: the capsule stays a sphere.
  EXPECT_NEAR(rotation_over_jeffery(capsule_parameters(700.0)), 1.0, 0.05);
}

// Membrane viscosity is objective: a sphere turning as a rigid body stretches no edge, so central
// edge friction leaves its rotation at half the shear rate, at the red cell's membrane viscosity
// (0.5 Pa s um, Boussinesq number eta_m / (eta R) ~ 200 here), through the implicit friction
// step. Fedosov's tangential friction resists every relative velocity, a rigid rotation's too,
// and slows it.
TEST(ShearRotation, CentralMembraneViscosityLeavesTheRotationFedosovsSlowsIt) {
  auto parameters = capsule_parameters(700.0);
  parameters.forces.push_back("viscosity");
  parameters.viscosity_Pa_s_um = 0.5;
  parameters.viscosity_split = "central";
  EXPECT_NEAR(rotation_over_jeffery(parameters), 1.0, 0.05);
  parameters.viscosity_split = "fedosov";
  EXPECT_LT(rotation_over_jeffery(parameters), 0.5);
}

}  // namespace
}  // namespace rbcsim::coupling
