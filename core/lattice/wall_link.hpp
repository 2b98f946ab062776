// Where a curved wall cuts a lattice link: the plain record the geometry module computes from a
// wall shape (geometry/wall_links.hpp) and the fluid solver consumes (FluidSolver::set_wall_links)
// for interpolated bounce-back (boundaries.hpp).
#pragma once

#include <cstddef>

namespace rbcsim::lattice {

// The wall fraction half-way bounce-back assumes on every link.
inline constexpr double kHalfwayFraction = 0.5;

struct WallLink {
  std::size_t node = 0;  // the fluid node, in grid order
  int direction = 0;     // D3Q19 direction c (d3q19.hpp) from the node into the wall node node + c
  // q in (0, 1]: distance from the node to the wall along the link, over the link length |c|.
  double fraction = kHalfwayFraction;
};

}  // namespace rbcsim::lattice
