// A short-range push of the membrane away from a wall. Without it a vertex that reaches the wall
// moves with the fluid there, which moves with the wall (no slip): the part of the cell that
// touches it sticks while the rest is carried on, and the membrane tears at its force limits. In
// reality a lubrication film keeps the cell off the wall; at dx = 0.5 um the lattice cannot
// resolve that film, so, as HemoCell does with its wall repulsion, a force stands in for it. It
// acts only within `range_um` of the wall, along the direction away from it:
//     F = force_at_wall_pN * (1 - d / range_um)^2,   d the distance to the wall,
// zero with zero slope at d = range_um, force_at_wall_pN at contact (and beyond, inside the wall,
// which the stability checks refuse anyway): WallLaw::pressure. Its push is finite at contact, so
// a cell pressed outward harder than that (in a crowded tube, squeezed between two neighbours
// whose surface contact grows without bound as they close in) goes through the wall. The barrier
// (WallLaw::barrier) is the cells' own surface contact law against the wall:
//     F = (force_at_wall_pN / 4) (range_um / d - 1)^2,   d floored at range_um / 100,
// equal to the pressure law at d = range_um / 2, weaker beyond it, and growing as (range_um / d)^2
// closer in, without a cap (a cap would again let a squeezed cell through).
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/vec3.hpp"

namespace rbcsim::cases {

// The wall's force law (suspension.wall_law; the header above).
enum class WallLaw { pressure, barrier };

// The laws' names (suspension.wall_law), one table for both ways (common/registry.hpp).
std::vector<std::string> wall_law_names();
std::string wall_law_name(WallLaw law);
// Throws InputError naming suspension.wall_law for a name not in wall_law_names().
WallLaw wall_law_named(std::string_view name);

struct WallRepulsion {
  double force_at_wall_pN = 0.0;  // 0: none; the pressure law's push at contact
  double range_um = 0.0;
  WallLaw law = WallLaw::pressure;
};

// The push of the wall on one vertex at distance distance_um from it (pN; 0 beyond the range).
double wall_push_pN(const WallRepulsion& repulsion, double distance_um);

// Where a point lies in a walled space: its distance to the nearest wall (negative beyond it) and
// the unit direction away from that wall, into the space (zero where there is none, on a tube's
// axis).
struct WallDistance {
  double distance_um = 0.0;
  Vec3 inward = Vec3::Zero();
};

// A tube along x with its axis at y = z = 0: the distance R - r along the inward radius (the
// wall taken as locally cylindrical, as at a gently varying throat).
WallDistance tube_wall_distance(const Vec3& position_um, double radius_um);

// A slab between flat walls at y = -half_gap_um and y = +half_gap_um: the nearer one.
WallDistance slab_wall_distance(const Vec3& position_um, double half_gap_um);

// Adds the repulsion of the wall that `wall` describes to forces_pN, one per position. Throws
// std::invalid_argument for a non-positive range with a non-zero force.
void add_wall_repulsion(std::span<const Vec3> positions_um,
                        const std::function<WallDistance(const Vec3& position_um)>& wall,
                        const WallRepulsion& repulsion, std::span<Vec3> forces_pN);

// The same for a tube along x (axis y = z = 0, lumen radius radius_um(x)).
void add_tube_wall_repulsion(std::span<const Vec3> positions_um,
                             const std::function<double(double x_um)>& radius_um,
                             const WallRepulsion& repulsion, std::span<Vec3> forces_pN);

}  // namespace rbcsim::cases
