// An axisymmetric cell built like the Evans-Fung discocyte: a midline curve in the meridian plane,
// thickened along its normal by a half-thickness that closes smoothly at the rim.
//
// With sigma in [0, 1] running from the axis (sigma = 0) to the rim (sigma = 1), the point of the
// unit sphere u = (sigma cos phi, sigma sin phi, u_z), u_z = +-sqrt(1 - sigma^2), maps to
//     (r, z) = midline(sigma) + u_z * thickness(sigma^2) * normal(sigma),   revolved by phi.
// The half-thickness is therefore sqrt(1 - sigma^2) * thickness(sigma^2): for a flat midline
// (R0 sigma, 0) and thickness (R0/2)(C0 + C2 s + C4 s^2) this is exactly Evans & Fung (1972). The
// map is smooth across the rim (u_z enters linearly), so the rim is as well resolved as the rest.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "mesh/surface_map.hpp"

namespace rbcsim::mesh {

struct ShellProfile {
  // (r, z) of the midline in um; r(0) = 0 and the midline must meet the axis at a right angle.
  std::function<Eigen::Vector2d(double sigma)> midline_um;
  // Unit normal of the midline towards the face that u_z > 0 maps to; normal(0) = (0, 1).
  std::function<Eigen::Vector2d(double sigma)> normal;
  // Half-thickness divided by sqrt(1 - sigma^2), in um, as a function of sigma^2.
  std::function<double(double sigma_squared)> thickness_um;
};

SurfaceMap thick_shell_map(ShellProfile profile);

}  // namespace rbcsim::mesh
