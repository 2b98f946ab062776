#include "geometry/voxelise.hpp"

#include <cmath>
#include <string>

#include "common/errors.hpp"

namespace rbcsim::geometry {
namespace {

// Relative slack so that an extent of exactly n dx, up to rounding, gives n nodes and not n + 1.
constexpr double kWholeNodeTolerance = 1e-9;
constexpr double kMaxNodesPerAxis = 1e6;

int nodes_along(double extent_um, double dx_um, bool open, int wall_layers) {
  const double spans = extent_um / dx_um;
  const double nodes =
      open ? std::max(1.0, std::round(spans))
           : std::max(1.0, std::ceil(spans - kWholeNodeTolerance)) + 2.0 * wall_layers;
  if (!(nodes <= kMaxNodesPerAxis)) {
    throw InputError("lattice grid", "the geometry would need " + std::to_string(nodes) +
                                         " nodes along one axis at dx = " + std::to_string(dx_um) +
                                         " um");
  }
  return static_cast<int>(nodes);
}

}  // namespace

SolidMask voxelise(const WallShape& shape, const LatticeGrid& grid) {
  validate_lattice_grid(grid);
  SolidMask mask(grid.node_count(), kSolid);
  for (int k = 0; k < grid.nz; ++k) {
    for (int j = 0; j < grid.ny; ++j) {
      shape.classify_row(grid, j, k,
                         std::span<std::uint8_t>(mask.data() + grid.index(0, j, k),
                                                 static_cast<std::size_t>(grid.nx)));
    }
  }
  return mask;
}

LatticeGrid lattice_around(const WallShape& shape, double dx_um, int wall_layers) {
  if (wall_layers < 1) {
    throw InputError("lattice grid",
                     "wall_layers must be at least 1, got " + std::to_string(wall_layers));
  }
  LatticeGrid grid;
  grid.dx_um = dx_um;
  validate_lattice_grid(grid);
  const auto bounds = shape.fluid_bounds();
  std::array<int, 3> dims{};
  for (int axis = 0; axis < 3; ++axis) {
    const double extent_um = bounds.max_um[axis] - bounds.min_um[axis];
    dims[axis] = nodes_along(extent_um, dx_um, bounds.open_axes[axis], wall_layers);
    const double centre_um = (bounds.min_um[axis] + bounds.max_um[axis]) / 2.0;
    grid.origin_um[axis] = centre_um - (dims[axis] - 1) * dx_um / 2.0;
  }
  grid.nx = dims[0];
  grid.ny = dims[1];
  grid.nz = dims[2];
  return grid;
}

}  // namespace rbcsim::geometry
