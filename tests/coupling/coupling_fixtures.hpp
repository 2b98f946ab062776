// Small coupled set-ups shared by the coupling tests: lattice units, fluids, spherical cells.
// The physics each test checks (and its analytic answer) stays in the test itself.
#pragma once

#include <memory>
#include <vector>

#include "coupling/coupled_simulation.hpp"
#include "lattice/fluid_solver.hpp"
#include "membrane/parameters.hpp"
#include "mesh/icosphere.hpp"
#include "units/unit_converter.hpp"

namespace rbcsim::coupling::testing {

// dx = 0.5 um, tau = 1, plasma (the defaults): dt = 1/6 * dx^2 / nu.
inline units::UnitConverter plasma_units() {
  return units::UnitConverter({0.5, 1.0, 1025.0, 1.1e-6});
}

// The icosphere of `level` with radius radius_um centred at centre_um.
inline mesh::TriangleMesh sphere_mesh(int level, double radius_um, const Vec3& centre_um) {
  auto sphere = mesh::unit_icosphere(level);
  for (Vec3& position : sphere.positions_um) position = centre_um + radius_um * position;
  return sphere;
}

// The vertices of `mesh` stretched by `factors` about `centre_um` (an ellipsoid from a sphere):
// a deformed shape whose membrane forces are far from zero.
inline std::vector<Vec3> stretched(const mesh::TriangleMesh& mesh, const Vec3& centre_um,
                                   const Vec3& factors) {
  std::vector<Vec3> positions;
  for (const Vec3& p : mesh.positions_um) {
    positions.push_back(centre_um + (p - centre_um).cwiseProduct(factors));
  }
  return positions;
}

// A fully periodic box of fluid at rest (TRT, tau 1).
inline std::unique_ptr<lattice::FluidSolver> periodic_fluid(int nx, int ny, int nz) {
  return std::make_unique<lattice::FluidSolver>(lattice::LatticeGrid(nx, ny, nz),
                                                lattice::FluidParameters{});
}

// A box of fluid at rest, periodic in x and z, with a Lees-Edwards sliding plane in y whose
// images move at velocity_difference (lattice units) relative to the box: simple shear.
inline std::unique_ptr<lattice::FluidSolver> lees_edwards_fluid(int nx, int ny, int nz,
                                                                double velocity_difference) {
  lattice::FluidParameters parameters;
  parameters.lees_edwards_velocity = velocity_difference;
  return std::make_unique<lattice::FluidSolver>(lattice::LatticeGrid(nx, ny, nz), parameters);
}

// Wall nodes in the planes y = 0 and y = ny - 1 (half-way walls at y = 1/2 and y = ny - 3/2),
// moving at -wall_speed and +wall_speed along x: Couette flow with zero velocity mid-gap.
inline std::unique_ptr<lattice::FluidSolver> couette_fluid(int nx, int ny, int nz,
                                                           double wall_speed) {
  auto fluid = periodic_fluid(nx, ny, nz);
  const auto& grid = fluid->grid();
  for (int z = 0; z < nz; ++z) {
    for (int x = 0; x < nx; ++x) {
      fluid->set_wall(grid.index(x, 0, z), {-wall_speed, 0.0, 0.0});
      fluid->set_wall(grid.index(x, ny - 1, z), {wall_speed, 0.0, 0.0});
    }
  }
  return fluid;
}

// Membrane parameters with only the link, area and volume terms, all of stiffness k: a capsule.
inline membrane::MembraneParameters capsule_parameters(double k_kBT) {
  membrane::MembraneParameters parameters;
  parameters.forces = {"link", "area", "volume"};
  parameters.k_link_kBT = k_kBT;
  parameters.k_area_kBT = k_kBT;
  parameters.k_volume_kBT = k_kBT;
  return parameters;
}

}  // namespace rbcsim::coupling::testing
