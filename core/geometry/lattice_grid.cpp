#include "geometry/lattice_grid.hpp"

#include <cmath>
#include <string>

#include "common/errors.hpp"

namespace rbcsim::geometry {

void validate_lattice_grid(const LatticeGrid& grid) {
  if (!std::isfinite(grid.dx_um) || grid.dx_um <= 0.0) {
    throw InputError("lattice grid",
                     "dx_um must be a positive length, got " + std::to_string(grid.dx_um));
  }
  if (!grid.origin_um.allFinite()) {
    throw InputError("lattice grid", "origin_um must be finite");
  }
  if (grid.nx < 1 || grid.ny < 1 || grid.nz < 1) {
    throw InputError("lattice grid", "dimensions must be at least 1 node, got " +
                                         std::to_string(grid.nx) + " x " + std::to_string(grid.ny) +
                                         " x " + std::to_string(grid.nz));
  }
}

}  // namespace rbcsim::geometry
