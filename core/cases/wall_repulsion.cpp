#include "cases/wall_repulsion.hpp"

#include <cmath>
#include <stdexcept>

namespace rbcsim::cases {

void add_wall_repulsion(std::span<const Vec3> positions_um,
                        const std::function<double(double x_um)>& radius_um,
                        const WallRepulsion& repulsion, std::span<Vec3> forces_pN) {
  if (repulsion.force_at_wall_pN == 0.0) return;
  if (!(repulsion.range_um > 0.0)) {
    throw std::invalid_argument("wall repulsion: the range must be > 0");
  }
  for (std::size_t v = 0; v < positions_um.size(); ++v) {
    const Vec3& position = positions_um[v];
    const double r_um = std::hypot(position.y(), position.z());
    const double distance_um = radius_um(position.x()) - r_um;
    if (distance_um >= repulsion.range_um || r_um == 0.0) continue;
    const double closeness = 1.0 - std::max(distance_um, 0.0) / repulsion.range_um;
    const double magnitude_pN = repulsion.force_at_wall_pN * closeness * closeness;
    forces_pN[v] -= magnitude_pN * Vec3(0.0, position.y(), position.z()) / r_um;
  }
}

}  // namespace rbcsim::cases
