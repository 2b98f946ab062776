#include "cases/wall_repulsion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/registry.hpp"

namespace rbcsim::cases {
namespace {

struct NamedWallLaw {
  std::string_view name;
  WallLaw law;
};
constexpr NamedWallLaw kWallLaws[] = {{"pressure", WallLaw::pressure},
                                      {"barrier", WallLaw::barrier}};

}  // namespace

std::vector<std::string> wall_law_names() { return entry_names(kWallLaws); }

std::string wall_law_name(WallLaw law) {
  for (const auto& entry : kWallLaws) {
    if (entry.law == law) return std::string(entry.name);
  }
  throw std::logic_error("wall law: not in the table");
}

WallLaw wall_law_named(std::string_view name) {
  return find_entry(kWallLaws, name, "suspension.wall_law").law;
}

WallDistance tube_wall_distance(const Vec3& position_um, double radius_um) {
  const double r_um = std::hypot(position_um.y(), position_um.z());
  if (r_um == 0.0) return {radius_um, Vec3::Zero()};
  return {radius_um - r_um, Vec3(0.0, -position_um.y() / r_um, -position_um.z() / r_um)};
}

WallDistance slab_wall_distance(const Vec3& position_um, double half_gap_um) {
  if (position_um.y() >= 0.0) return {half_gap_um - position_um.y(), -Vec3::UnitY()};
  return {half_gap_um + position_um.y(), Vec3::UnitY()};
}

double wall_push_pN(const WallRepulsion& repulsion, double distance_um) {
  const double range = repulsion.range_um;
  if (distance_um >= range) return 0.0;
  if (repulsion.law == WallLaw::barrier) {
    const double excess = range / std::max(distance_um, 0.01 * range) - 1.0;
    return 0.25 * repulsion.force_at_wall_pN * excess * excess;
  }
  const double closeness = 1.0 - std::max(distance_um, 0.0) / range;
  return repulsion.force_at_wall_pN * closeness * closeness;
}

void add_wall_repulsion(std::span<const Vec3> positions_um,
                        const std::function<WallDistance(const Vec3& position_um)>& wall,
                        const WallRepulsion& repulsion, std::span<Vec3> forces_pN) {
  if (repulsion.force_at_wall_pN == 0.0) return;
  if (!(repulsion.range_um > 0.0)) {
    throw std::invalid_argument("wall repulsion: the range must be > 0");
  }
  for (std::size_t v = 0; v < positions_um.size(); ++v) {
    const auto [distance_um, inward] = wall(positions_um[v]);
    if (distance_um >= repulsion.range_um) continue;
    forces_pN[v] += wall_push_pN(repulsion, distance_um) * inward;
  }
}

void add_tube_wall_repulsion(std::span<const Vec3> positions_um,
                             const std::function<double(double x_um)>& radius_um,
                             const WallRepulsion& repulsion, std::span<Vec3> forces_pN) {
  add_wall_repulsion(
      positions_um,
      [&radius_um](const Vec3& position) {
        return tube_wall_distance(position, radius_um(position.x()));
      },
      repulsion, forces_pN);
}

}  // namespace rbcsim::cases
