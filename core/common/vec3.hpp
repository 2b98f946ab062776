// The one 3-vector type of the project. Positions of mesh vertices are in micrometres and
// membrane forces in piconewtons unless a name says otherwise (see core/units).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace rbcsim {

using Vec3 = Eigen::Vector3d;

}  // namespace rbcsim
