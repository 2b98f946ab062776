// Two parallel plates normal to y at y = -gap/2 and y = +gap/2: the walls of the moving-wall
// (Couette) shear set-up (docs/physics.md, "Shear"). Flow along x, velocity gradient along y,
// vorticity along z; x and z are open (periodic).
#pragma once

#include <string_view>

#include "geometry/wall_shape.hpp"

namespace rbcsim::geometry {

struct ChannelParameters {
  double gap_um = 0.0;     // distance between the plates (y)
  double length_um = 0.0;  // extent of the domain along the flow (x)
  double width_um = 0.0;   // extent of the domain along the vorticity axis (z)
};

class ChannelWall final : public WallShape {
 public:
  // Throws rbcsim::InputError naming source.<parameter> for a non-positive length.
  explicit ChannelWall(const ChannelParameters& parameters, std::string_view source = "channel");

  bool is_fluid(const Vec3& point_um) const override;
  FluidBounds fluid_bounds() const override;
  const ChannelParameters& parameters() const { return parameters_; }

 private:
  ChannelParameters parameters_;
};

}  // namespace rbcsim::geometry
