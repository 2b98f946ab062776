// The one 3-vector type of the project. Positions of mesh vertices are in micrometres and
// membrane forces in piconewtons unless a name says otherwise (see core/units).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace rbcsim {

using Vec3 = Eigen::Vector3d;

// Three draws of `distribution`, for x, y and z in that order. Vec3(d(g), d(g), d(g)) would leave
// the order to the compiler (a call's arguments are not sequenced; GCC and clang differ), and a
// seeded test or benchmark must see the same numbers whatever compiled it.
template <class Distribution, class Generator>
Vec3 random_vec3(Distribution& distribution, Generator& generator) {
  Vec3 drawn;
  for (int axis = 0; axis < 3; ++axis) drawn[axis] = distribution(generator);
  return drawn;
}

}  // namespace rbcsim
