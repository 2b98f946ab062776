#include "lattice/lattice_grid.hpp"

#include "common/errors.hpp"

#include <string>

namespace rbcsim::lattice {

LatticeGrid::LatticeGrid(int nx, int ny, int nz) : nx_(nx), ny_(ny), nz_(nz) {
  if (nx < 1 || ny < 1 || nz < 1) {
    throw InputError("lattice grid", "every extent must be at least 1 node, got " +
                                         std::to_string(nx) + " x " + std::to_string(ny) + " x " +
                                         std::to_string(nz));
  }
  node_count_ =
      static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz);
}

std::array<int, 3> LatticeGrid::coordinates(std::size_t node) const {
  const auto row = node / static_cast<std::size_t>(nx_);
  return {static_cast<int>(node % static_cast<std::size_t>(nx_)),
          static_cast<int>(row % static_cast<std::size_t>(ny_)),
          static_cast<int>(row / static_cast<std::size_t>(ny_))};
}

std::size_t LatticeGrid::periodic_neighbour(std::size_t node,
                                            const std::array<int, 3>& offset) const {
  const auto [x, y, z] = coordinates(node);
  return index(wrap(x + offset[0], nx_), wrap(y + offset[1], ny_), wrap(z + offset[2], nz_));
}

}  // namespace rbcsim::lattice
