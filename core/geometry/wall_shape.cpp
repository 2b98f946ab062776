#include "geometry/wall_shape.hpp"

namespace rbcsim::geometry {

std::optional<double> WallShape::radius_at_um(double /*x_um*/) const { return std::nullopt; }

void WallShape::classify_row(const LatticeGrid& grid, int j, int k,
                             std::span<std::uint8_t> solid_row) const {
  for (int i = 0; i < grid.nx; ++i) {
    solid_row[i] = is_fluid(grid.node_position_um(i, j, k)) ? kFluid : kSolid;
  }
}

}  // namespace rbcsim::geometry
