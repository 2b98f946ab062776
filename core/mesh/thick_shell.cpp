#include "mesh/thick_shell.hpp"

#include <algorithm>
#include <cmath>

namespace rbcsim::mesh {

SurfaceMap thick_shell_map(ShellProfile profile) {
  return [profile = std::move(profile)](const Vec3& u) {
    const double sigma = std::min(1.0, std::hypot(u.x(), u.y()));
    const Eigen::Vector2d meridian_point =
        profile.midline_um(sigma) +
        u.z() * profile.thickness_um(sigma * sigma) * profile.normal(sigma);
    // On the axis the azimuth is undefined but r is zero there.
    const double radial_scale = sigma > 0.0 ? meridian_point.x() / sigma : 0.0;
    return Vec3(radial_scale * u.x(), radial_scale * u.y(), meridian_point.y());
  };
}

}  // namespace rbcsim::mesh
