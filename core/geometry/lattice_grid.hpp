// The Eulerian lattice as the geometry module sees it: a box of nx * ny * nz nodes, spacing dx_um.
//
// Node-centred convention: node (i, j, k) sits AT origin_um + (i, j, k) * dx_um (it is not the
// corner of a cell). With half-way bounce-back (docs/physics.md) a wall lies halfway between a
// fluid node and its solid neighbour, so each fluid node owns the cube of side dx centred on it
// and a channel of n fluid nodes across is n * dx wide.
//
// Node (i, j, k) is stored at index i + nx * (j + ny * k): x runs fastest, as in the lattice
// solver's arrays, so one x-row of nodes is contiguous.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/vec3.hpp"

namespace rbcsim::geometry {

struct LatticeGrid {
  Vec3 origin_um = Vec3::Zero();  // position of node (0, 0, 0)
  double dx_um = 1.0;
  int nx = 1;
  int ny = 1;
  int nz = 1;

  std::size_t node_count() const {
    return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) *
           static_cast<std::size_t>(nz);
  }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(nx) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(ny) * k);
  }
  Vec3 node_position_um(int i, int j, int k) const { return origin_um + dx_um * Vec3(i, j, k); }
};

// One byte per node, indexed as LatticeGrid::index: 1 = solid (wall), 0 = fluid.
using SolidMask = std::vector<std::uint8_t>;
inline constexpr std::uint8_t kSolid = 1;
inline constexpr std::uint8_t kFluid = 0;

// Throws rbcsim::InputError ("lattice grid: ...") for a non-positive or non-finite dx_um, a
// non-finite origin or a dimension below 1.
void validate_lattice_grid(const LatticeGrid& grid);

}  // namespace rbcsim::geometry
