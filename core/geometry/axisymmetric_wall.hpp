// A circular tube along x, from x = 0 to x = length, whose lumen radius may vary with x. Beyond
// the ends the lumen continues with the radius it has there (the x axis is open: inflow/outflow).
#pragma once

#include "geometry/wall_shape.hpp"

namespace rbcsim::geometry {

class AxisymmetricWall : public WallShape {
 public:
  bool is_fluid(const Vec3& point_um) const final;
  FluidBounds fluid_bounds() const final;
  std::optional<double> radius_at_um(double x_um) const final { return lumen_radius_um(x_um); }

  virtual double lumen_radius_um(double x_um) const = 0;
  virtual double largest_radius_um() const = 0;
  virtual double length_um() const = 0;
};

}  // namespace rbcsim::geometry
