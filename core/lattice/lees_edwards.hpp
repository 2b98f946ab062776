// Lees-Edwards sliding periodic boundary in y, for wall-free simple shear (Lees & Edwards 1972; for
// lattice Boltzmann, Wagner & Pagonabarraga, J. Stat. Phys. 107, 521 (2002)).
//
// The image of the box above (y + ny) is displaced by offset(t) = U t along x and moves at +U; the
// image below is displaced by -offset and moves at -U. The steady state is simple shear at rate
// U/ny, u_x = (U/ny)(y - (ny - 1)/2), which is +U/2 and -U/2 at the sliding planes y = ny - 1/2
// and y = -1/2. A population that crosses a sliding plane is taken from the displaced image:
//  * position: from x - c_x + offset when it enters through the bottom plane, x - c_x - offset
//    through the top one, linearly interpolated between the two nearest nodes of that row. The
//    weights sum to one over a periodic row, so mass is conserved exactly.
//  * velocity: Galilean shift by the image velocity, f_i + f_i^eq(rho, u + dU) - f_i^eq(rho, u),
//  with
//    rho, u those of the source node and dU = -U through the bottom plane, +U through the top. The
//    shifts of the five directions that cross a plane together carry no mass.
// The offset used for a stream step is that of the arrival time.
#pragma once

#include "lattice/d3q19.hpp"
#include "lattice/fluid_kernel.hpp"
#include "lattice/lattice_grid.hpp"

#include <array>
#include <cstddef>

namespace rbcsim::lattice {

// offset(t) = U t mod nx, in [0, nx).
double lees_edwards_offset(double velocity_difference, std::size_t time, int nx);

// Where the populations entering one sliding plane come from.
struct LeesEdwardsPlane {
  int entering_cy;        // +1: entering through the bottom plane (target y = 0); -1: the top one
  int target_y;           // the row of nodes the populations enter
  int source_y;           // the row of the image they leave
  double displacement;    // +offset (bottom) or -offset (top)
  double velocity_shift;  // -U (bottom) or +U (top)
};

// The two planes, bottom first.
std::array<LeesEdwardsPlane, 2> lees_edwards_planes(int ny, double offset,
                                                    double velocity_difference);

struct LeesEdwardsSource {
  int x_low;        // first source node along x
  int x_high;       // second source node along x, (x_low + 1) mod nx
  double fraction;  // weight of x_high; x_low gets 1 - fraction
};

// Source along x of the population with velocity x-component `cx` arriving at `x`.
LeesEdwardsSource lees_edwards_source(int x, int cx, double displacement, int nx);

// f_i^eq(rho, u + dU e_x) - f_i^eq(rho, u).
constexpr double galilean_shift(int direction, double density,
                                const std::array<double, 3>& velocity, double shift_x) {
  const std::array<double, 3> shifted = {velocity[0] + shift_x, velocity[1], velocity[2]};
  return equilibrium(direction, density, shifted) - equilibrium(direction, density, velocity);
}

// The population f_i entering node (x, plane.target_y, z) through a sliding plane.
// `post_collision(node)` returns f*_i(node) wherever the calling kernel keeps it; density and
// velocity of the source nodes come from `arrays` (those of the collision that produced f*).
template <class PostCollision>
double lees_edwards_population(const LatticeGrid& grid, const LeesEdwardsPlane& plane,
                               int direction, int x, int z, const FluidArrays& arrays,
                               PostCollision&& post_collision) {
  const auto& c = kVelocities[direction];
  const int source_z = LatticeGrid::wrap(z - c[2], grid.nz());
  const auto source = lees_edwards_source(x, c[0], plane.displacement, grid.nx());
  const auto shifted = [&](int source_x) {
    const std::size_t node = grid.index(source_x, plane.source_y, source_z);
    const std::array<double, 3> velocity = {arrays.velocity[0][node], arrays.velocity[1][node],
                                            arrays.velocity[2][node]};
    return post_collision(node) +
           galilean_shift(direction, arrays.density[node], velocity, plane.velocity_shift);
  };
  return (1.0 - source.fraction) * shifted(source.x_low) + source.fraction * shifted(source.x_high);
}

}  // namespace rbcsim::lattice
