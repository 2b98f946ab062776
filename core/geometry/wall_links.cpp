#include "geometry/wall_links.hpp"

#include <stdexcept>

#include "lattice/d3q19.hpp"
#include "lattice/lattice_grid.hpp"

namespace rbcsim::geometry {
namespace {

// The fraction along [from, to] where the shape turns from fluid to solid.
double wall_fraction_along(const WallShape& shape, const Vec3& from_um, const Vec3& to_um) {
  if (!shape.is_fluid(from_um) || shape.is_fluid(to_um)) {
    return lattice::kHalfwayFraction;
  }
  double fluid = 0.0;
  double solid = 1.0;
  while (solid - fluid > kWallFractionTolerance) {
    const double middle = 0.5 * (fluid + solid);
    (shape.is_fluid(from_um + middle * (to_um - from_um)) ? fluid : solid) = middle;
  }
  return 0.5 * (fluid + solid);
}

// Appends the links from fluid node (i, j, k) to its solid neighbours.
void append_node_links(const WallShape& shape, const LatticeGrid& grid, const SolidMask& solid_mask,
                       int i, int j, int k, std::vector<lattice::WallLink>& links) {
  constexpr auto wrap = &lattice::LatticeGrid::wrap;  // the lattice's periodic neighbours
  for (int direction = 1; direction < lattice::kDirections; ++direction) {
    const auto& c = lattice::kVelocities[direction];
    const std::size_t neighbour =
        grid.index(wrap(i + c[0], grid.nx), wrap(j + c[1], grid.ny), wrap(k + c[2], grid.nz));
    if (solid_mask[neighbour] != kFluid) {
      links.push_back({grid.index(i, j, k), direction,
                       wall_fraction_along(shape, grid.node_position_um(i, j, k),
                                           grid.node_position_um(i + c[0], j + c[1], k + c[2]))});
    }
  }
}

}  // namespace

std::vector<lattice::WallLink> wall_link_fractions(const WallShape& shape, const LatticeGrid& grid,
                                                   const SolidMask& solid_mask) {
  validate_lattice_grid(grid);
  if (solid_mask.size() != grid.node_count()) {
    throw std::invalid_argument("wall_link_fractions: the mask must have one entry per node");
  }
  std::vector<lattice::WallLink> links;
  for (int k = 0; k < grid.nz; ++k) {
    for (int j = 0; j < grid.ny; ++j) {
      for (int i = 0; i < grid.nx; ++i) {
        if (solid_mask[grid.index(i, j, k)] == kFluid) {
          append_node_links(shape, grid, solid_mask, i, j, k, links);
        }
      }
    }
  }
  return links;
}

}  // namespace rbcsim::geometry
