#include "lattice/boundaries.hpp"

#include <algorithm>

namespace rbcsim::lattice {

BoundaryMap::BoundaryMap(std::size_t node_count) : kinds_(node_count, 0) {}

void BoundaryMap::set_wall(std::size_t node, const std::array<double, 3>& wall_velocity) {
  kinds_.at(node) = static_cast<std::uint8_t>(NodeKind::wall);
  outlet_density_.erase(node);
  if (wall_velocity == std::array<double, 3>{0.0, 0.0, 0.0}) {
    wall_velocity_.erase(node);
  } else {
    wall_velocity_[node] = wall_velocity;
  }
}

void BoundaryMap::set_pressure_outlet(std::size_t node, double density) {
  kinds_.at(node) = static_cast<std::uint8_t>(NodeKind::pressure_outlet);
  wall_velocity_.erase(node);
  outlet_density_[node] = density;
}

std::size_t BoundaryMap::fluid_node_count() const {
  return static_cast<std::size_t>(std::count(kinds_.begin(), kinds_.end(), std::uint8_t{0}));
}

std::array<double, 3> BoundaryMap::wall_velocity(std::size_t node) const {
  const auto found = wall_velocity_.find(node);
  return found == wall_velocity_.end() ? std::array<double, 3>{0.0, 0.0, 0.0} : found->second;
}

double BoundaryMap::outlet_density(std::size_t node) const { return outlet_density_.at(node); }

}  // namespace rbcsim::lattice
