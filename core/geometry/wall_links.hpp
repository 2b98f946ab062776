// Where the walls of a shape cut the lattice links: the wall fraction q of every link from a fluid
// node to a solid node, for interpolated (curved-wall) bounce-back in the lattice solver
// (lattice/boundaries.hpp, FluidSolver::set_wall_links).
#pragma once

#include <vector>

#include "geometry/lattice_grid.hpp"
#include "geometry/wall_shape.hpp"
#include "lattice/wall_link.hpp"

namespace rbcsim::geometry {

// Along a link shorter than this fraction of its length the wall position is not resolved further.
inline constexpr double kWallFractionTolerance = 1e-10;

// For every fluid node of `solid_mask` and every D3Q19 direction c whose neighbour node + c is
// solid, the fraction q in (0, 1] of the link at which the shape's wall lies: the wall point is
// node + q c (in units of dx_um), found by bisection on shape.is_fluid to kWallFractionTolerance.
// Neighbours wrap periodically along every axis, as on the lattice; the link itself runs straight
// on in space (beyond an open end a tube continues with its end radius). Where the shape does not
// change from fluid to solid along the link (a mask made by another rule, or a wrap across open
// ends that differ), the link gets the half-way fraction 1/2, as the staircase assumes. A link
// that crosses the wall several times (a wall thinner than dx) gets one of the crossings. Links are
// listed by node, then direction. Throws std::invalid_argument if the mask does not have
// grid.node_count() entries, rbcsim::InputError for an invalid grid.
std::vector<lattice::WallLink> wall_link_fractions(const WallShape& shape, const LatticeGrid& grid,
                                                   const SolidMask& solid_mask);

}  // namespace rbcsim::geometry
