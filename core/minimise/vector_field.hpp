// Sums over a field of one Vec3 per point, in point order (so they do not depend on threads).
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include "common/vec3.hpp"

namespace rbcsim::minimise {

inline double dot(std::span<const Vec3> a, std::span<const Vec3> b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i].dot(b[i]);
  return sum;
}

inline double norm(std::span<const Vec3> vectors) { return std::sqrt(dot(vectors, vectors)); }

inline double max_norm(std::span<const Vec3> vectors) {
  double largest = 0.0;
  for (const auto& v : vectors) largest = std::max(largest, v.norm());
  return largest;
}

}  // namespace rbcsim::minimise
