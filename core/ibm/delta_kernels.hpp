// Discrete delta functions of the immersed boundary method (docs/physics.md), registered by name in
// one table ("ibm.kernel": "phi2" | "phi3" | "phi4"). Each is given by its 1D weight phi(r) of the
// offset r = point - node (in lattice spacings) and its support width (nodes per axis); the 3D
// weight is the product phi(rx) phi(ry) phi(rz). With dx = 1 a weight is already per unit volume.
#pragma once

#include <cmath>
#include <span>
#include <string_view>

#include "common/vec3.hpp"

namespace rbcsim::ibm {

// The widest registered support: a stencil holds at most 4^3 = 64 nodes per point.
inline constexpr int kMaxSupportWidth = 4;

struct DeltaKernel {
  std::string_view name;
  int support_width;  // phi(r) = 0 for |r| >= support_width / 2
  double (*weight_1d)(double offset);
  std::string_view description;
};

// Every registered kernel, in table order.
std::span<const DeltaKernel> delta_kernels();

// Throws InputError("ibm.kernel", ...) naming the known kernels when `name` is not one of them.
const DeltaKernel& find_delta_kernel(std::string_view name);

// The first of the support_width lattice nodes n with coordinate - width/2 < n <= coordinate +
// width/2 along one axis: every node the kernel can reach from `coordinate`.
inline int first_node_in_support(const DeltaKernel& kernel, double coordinate) {
  return static_cast<int>(std::floor(coordinate - 0.5 * kernel.support_width)) + 1;
}

inline double weight_3d(const DeltaKernel& kernel, const Vec3& offset) {
  return kernel.weight_1d(offset.x()) * kernel.weight_1d(offset.y()) * kernel.weight_1d(offset.z());
}

}  // namespace rbcsim::ibm
