// The hematocrit profile of a suspension in a straight tube (docs/physics.md, "Suspensions"): the
// volume fraction of cells in rings of equal width about the tube's axis (x, at y = z = 0).
//
// Measured along lines parallel to the axis, on a square grid in the cross-section: a line's length
// inside a cell is the sum over the cell's surface crossings, sorted along x and taken in pairs
// (entry, exit). The crossings are found by projecting each triangle onto the cross-section with a
// watertight rule (a line through a shared edge or vertex meets exactly one of the triangles that
// share it), so every closed surface is crossed an even number of times. Cells need not be wrapped
// into the period: the length inside a cell does not depend on where along x it lies. Where cells
// overlap, the overlap counts once per cell.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::cases {

struct RadialProfileGrid {
  double radius_um = 0.0;
  double length_um = 0.0;
  std::size_t rings = 10;  // of width radius_um / rings, the first about the axis
  // Lines per radius along y and along z: spacing radius_um / lines_per_radius.
  std::size_t lines_per_radius = 50;
};

// The volume fraction of cells in each ring: the cells' length inside, summed over the ring's
// lines, over (lines x length_um). `positions_um[c]` and `triangles[c]` are cell c's closed
// surface. Throws std::invalid_argument for a grid without a line in some ring (rings >
// lines_per_radius / 2) or a non-positive size, and std::logic_error for a surface crossed an odd
// number of times (not closed).
std::vector<double> radial_volume_fraction(
    std::span<const std::vector<Vec3>> positions_um,
    std::span<const std::span<const mesh::Triangle>> triangles, const RadialProfileGrid& grid);

}  // namespace rbcsim::cases
