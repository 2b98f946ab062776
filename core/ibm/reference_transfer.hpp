// The plain reference of spreading and interpolation (docs/architecture.md: every hot kernel keeps
// one): serial loops over each point's support box that evaluate the kernel on the fly, with the
// same rules as InterpolationStencil (periodic wrap, nodes outside a non-periodic grid and solid
// nodes dropped, the rest renormalised to sum 1). The optimised stencil path is tested against it.
// Throws RuntimeFailure for a point with no fluid node in reach.
#pragma once

#include <cstdint>
#include <span>

#include "common/vec3.hpp"
#include "ibm/delta_kernels.hpp"
#include "ibm/grid_view.hpp"

namespace rbcsim::ibm::reference {

void spread_forces(const DeltaKernel& kernel, const GridView& grid, const std::uint8_t* solid_mask,
                   std::span<const Vec3> positions_lu, std::span<const Vec3> point_forces_lu,
                   double* fx, double* fy, double* fz);

void interpolate_velocity(const DeltaKernel& kernel, const GridView& grid,
                          const std::uint8_t* solid_mask, std::span<const Vec3> positions_lu,
                          const double* ux, const double* uy, const double* uz,
                          std::span<Vec3> out_velocities_lu);

}  // namespace rbcsim::ibm::reference
