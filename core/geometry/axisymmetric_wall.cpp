#include "geometry/axisymmetric_wall.hpp"

namespace rbcsim::geometry {

bool AxisymmetricWall::is_fluid(const Vec3& point_um) const {
  const double radius_um = lumen_radius_um(point_um.x());
  return point_um.y() * point_um.y() + point_um.z() * point_um.z() < radius_um * radius_um;
}

FluidBounds AxisymmetricWall::fluid_bounds() const {
  const double radius_um = largest_radius_um();
  return {Vec3(0.0, -radius_um, -radius_um),
          Vec3(length_um(), radius_um, radius_um),
          {true, false, false}};
}

}  // namespace rbcsim::geometry
