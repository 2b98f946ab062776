// How the immersed-boundary kernels see the lattice: a box of nx * ny * nz nodes, node (i, j, k) at
// the position (i, j, k) in lattice spacings, stored at index i + nx * (j + ny * k) in every
// per-node array (force density, velocity, solid mask). The IBM works on such plain arrays so that
// it plugs onto the lattice solver's fields whatever their storage (docs/architecture.md).
#pragma once

#include <cstddef>

namespace rbcsim::ibm {

struct GridView {
  int nx = 0, ny = 0, nz = 0;
  bool periodic_x = false, periodic_y = false, periodic_z = false;

  friend bool operator==(const GridView&, const GridView&) = default;
};

inline std::size_t node_count(const GridView& grid) {
  return static_cast<std::size_t>(grid.nx) * static_cast<std::size_t>(grid.ny) *
         static_cast<std::size_t>(grid.nz);
}

inline std::size_t node_index(const GridView& grid, int i, int j, int k) {
  return static_cast<std::size_t>(i) +
         static_cast<std::size_t>(grid.nx) *
             (static_cast<std::size_t>(j) +
              static_cast<std::size_t>(grid.ny) * static_cast<std::size_t>(k));
}

// Axis 0, 1, 2 = x, y, z.
inline int axis_extent(const GridView& grid, int axis) {
  return axis == 0 ? grid.nx : axis == 1 ? grid.ny : grid.nz;
}
inline bool axis_periodic(const GridView& grid, int axis) {
  return axis == 0 ? grid.periodic_x : axis == 1 ? grid.periodic_y : grid.periodic_z;
}

// The stored node number along one axis of lattice coordinate n (which may lie outside the grid):
// wrapped into [0, extent) on a periodic axis; -1 (no such node) outside [0, extent) otherwise.
inline int wrap_or_drop(int n, int extent, bool periodic) {
  if (n >= 0 && n < extent) return n;
  if (!periodic) return -1;
  // Only nodes beyond a periodic face get here: pay for the division then.
  const int remainder = n % extent;
  return remainder < 0 ? remainder + extent : remainder;
}

}  // namespace rbcsim::ibm
