#include "geometry/channel_wall.hpp"

#include <cmath>

#include "geometry/shape_parameters.hpp"

namespace rbcsim::geometry {

ChannelWall::ChannelWall(const ChannelParameters& parameters, std::string_view source)
    : parameters_(parameters) {
  require_positive_length(parameters.gap_um, source, "gap_um");
  require_positive_length(parameters.length_um, source, "length_um");
  require_positive_length(parameters.width_um, source, "width_um");
}

bool ChannelWall::is_fluid(const Vec3& point_um) const {
  return std::abs(point_um.y()) < parameters_.gap_um / 2.0;
}

FluidBounds ChannelWall::fluid_bounds() const {
  const double half_gap = parameters_.gap_um / 2.0;
  const double half_width = parameters_.width_um / 2.0;
  return {Vec3(0.0, -half_gap, -half_width),
          Vec3(parameters_.length_um, half_gap, half_width),
          {true, false, true}};
}

}  // namespace rbcsim::geometry
