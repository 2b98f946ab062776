#include "lattice/boundaries.hpp"

#include "common/registry.hpp"

#include <algorithm>

namespace rbcsim::lattice {
namespace {

WallLinkWeights halfway_weights(double /*fraction*/, bool /*behind_is_fluid*/) {
  return kHalfwayWeights;
}

// Bouzidi, Firdaouss & Lallemand, Phys. Fluids 13, 3452 (2001), the linear version; the
// moving-wall term as in Lallemand & Luo, J. Comput. Phys. 184, 406 (2003). For q < 1/2 the
// population that reaches x after its reflection leaves x + (1 - 2q) c_i: interpolate it between
// x and x + c_i. For q >= 1/2 the reflected f*_h(x) lands at x + (2q - 1) c_h: interpolate the
// arrival at x between that point and x + c_i, where f*_i(x) arrives. Both interpolations are
// exact for populations linear in space. Without a fluid node x + c_i the q < 1/2 form falls back
// to half-way bounce-back.
WallLinkWeights bouzidi_weights(double fraction, bool behind_is_fluid) {
  const double twice = 2.0 * fraction;
  if (fraction >= 0.5) {
    return {1.0 / twice, (twice - 1.0) / twice, 0.0, 1.0 / twice};
  }
  if (!behind_is_fluid) {
    return kHalfwayWeights;
  }
  return {twice, 0.0, 1.0 - twice, 1.0};
}

constexpr std::array kWallRules = {
    WallRule{"halfway", "half-way bounce-back: every wall half-way along its links (staircase)",
             halfway_weights},
    WallRule{"bouzidi",
             "linearly interpolated bounce-back at the wall fraction q of each link (Bouzidi, "
             "Firdaouss & Lallemand 2001)",
             bouzidi_weights},
};

std::size_t link_key(std::size_t node, int direction) {
  return node * kDirections + static_cast<std::size_t>(direction);
}

}  // namespace

std::span<const WallRule> wall_rules() { return kWallRules; }

const WallRule& find_wall_rule(std::string_view name) {
  return find_entry(kWallRules, name, "lattice.wall_rule");
}

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

void BoundaryMap::set_wall_fraction(const WallLink& link) {
  wall_fraction_[link_key(link.node, link.direction)] = link.fraction;
}

double BoundaryMap::wall_fraction(std::size_t node, int direction) const {
  const auto found = wall_fraction_.find(link_key(node, direction));
  return found == wall_fraction_.end() ? kHalfwayFraction : found->second;
}

}  // namespace rbcsim::lattice
