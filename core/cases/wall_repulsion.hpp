// A short-range push of the membrane away from a circular tube wall. Without it a vertex that
// reaches the wall moves with the fluid there, which is at rest (no slip): the part of the cell
// that touches the throat sticks while the rest is carried on, and the membrane tears at its force
// limits. In reality a lubrication film keeps the cell off the wall; at dx = 0.5 um the lattice
// cannot resolve that film, so, as HemoCell does with its wall repulsion, a force stands in for
// it. It acts only within `range_um` of the wall, along the inward radius:
//     F = force_at_wall_pN * (1 - d / range_um)^2,   d = R(x) - r (distance to the wall),
// zero with zero slope at d = range_um, force_at_wall_pN at contact (and beyond, inside the wall,
// which the stability checks refuse anyway).
#pragma once

#include <functional>
#include <span>

#include "common/vec3.hpp"

namespace rbcsim::cases {

struct WallRepulsion {
  double force_at_wall_pN = 0.0;  // 0: none
  double range_um = 0.0;
};

// Adds the repulsion of a tube along x (axis y = z = 0, lumen radius radius_um(x)) to forces_pN,
// one per position. Throws std::invalid_argument for a non-positive range with a non-zero force.
void add_wall_repulsion(std::span<const Vec3> positions_um,
                        const std::function<double(double x_um)>& radius_um,
                        const WallRepulsion& repulsion, std::span<Vec3> forces_pN);

}  // namespace rbcsim::cases
