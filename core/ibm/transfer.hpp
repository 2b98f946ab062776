// Force spreading and velocity interpolation through a prebuilt InterpolationStencil
// (docs/architecture.md, one coupled step: steps 2 and 4), on the lattice's plain per-node arrays
// in lattice units. With the same stencil, spreading is the exact adjoint of interpolation:
//   sum_nodes u . (S F) = sum_points (I u) . F.
// Both throw std::invalid_argument when the stencil was built for another grid or another
// number of points.
#pragma once

#include <span>

#include "common/vec3.hpp"
#include "ibm/grid_view.hpp"
#include "ibm/interpolation_stencil.hpp"

namespace rbcsim::ibm {

// Adds each point's force times its weights to the force density (fx, fy, fz): one value per
// node. dx = 1, so the weights are already per unit volume: the density is in lattice force
// units per lattice volume, and its sum equals the sum of the point forces.
//
// Deterministic whatever the number of OpenMP threads, bit for bit: each thread owns a contiguous
// range of node indices and walks all points in index order, adding only to the nodes it owns.
// Every node thus receives its contributions in the same order (point index, then stencil slot)
// as in a serial loop, with no atomics and no per-thread copies of the force field.
void spread_forces(const InterpolationStencil& stencil, std::span<const Vec3> point_forces_lu,
                   const GridView& grid, double* fx, double* fy, double* fz);

// One set of points to spread (a cell's vertices): its stencil and one force per point.
struct SpreadSource {
  const InterpolationStencil* stencil;
  std::span<const Vec3> point_forces_lu;
};
// The same for several point sets in one parallel region: every node receives its contributions
// source by source in the given order, then point by point, so the density is bit-identical to
// spreading the sources one after the other, whatever the thread count. Throws as above for the
// first source that does not fit, before adding anything.
void spread_forces(std::span<const SpreadSource> sources, const GridView& grid, double* fx,
                   double* fy, double* fz);

// Writes, for each point, the weighted sum of the node velocities (ux, uy, uz) over its stencil.
// Pass the lattice's Guo-corrected velocity u = (sum f c + F/2) / rho.
void interpolate_velocity(const InterpolationStencil& stencil, const GridView& grid,
                          const double* ux, const double* uy, const double* uz,
                          std::span<Vec3> out_velocities_lu);

}  // namespace rbcsim::ibm
