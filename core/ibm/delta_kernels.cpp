#include "ibm/delta_kernels.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/registry.hpp"

namespace rbcsim::ibm {
namespace {

// 2-point hat: linear (trilinear in 3D) interpolation, HemoCell's default. Zeroth and first
// moments are exact, so it reproduces linear fields.
double phi2(double offset) {
  const double r = std::abs(offset);
  return r < 1.0 ? 1.0 - r : 0.0;
}

// Roma, Peskin & Berger (1999, J. Comput. Phys. 153:509) 3-point function: zeroth and first
// moments exact and sum of squares 1/2 for every offset. The outer branch vanishes at |r| = 1.5,
// where round-off could make it a hair negative: clamp.
double phi3(double offset) {
  const double r = std::abs(offset);
  if (r <= 0.5) return (1.0 + std::sqrt(1.0 - 3.0 * r * r)) / 3.0;
  if (r < 1.5) {
    const double one_minus_r = 1.0 - r;
    return std::max(0.0, (5.0 - 3.0 * r - std::sqrt(1.0 - 3.0 * one_minus_r * one_minus_r)) / 6.0);
  }
  return 0.0;
}

// Peskin's standard 4-point function (Peskin 2002, Acta Numerica 11:479, eq. 6.27): zeroth and
// first moments exact, even and odd nodes each carry 1/2, sum of squares 3/8. Chosen over the
// cosine 4-point function, whose moments are only approximate.
double phi4(double offset) {
  const double r = std::abs(offset);
  if (r <= 1.0) return (3.0 - 2.0 * r + std::sqrt(1.0 + 4.0 * r - 4.0 * r * r)) / 8.0;
  if (r < 2.0) {
    return std::max(0.0, (5.0 - 2.0 * r - std::sqrt(-7.0 + 12.0 * r - 4.0 * r * r)) / 8.0);
  }
  return 0.0;
}

constexpr std::array kKernels{
    DeltaKernel{"phi2", 2, phi2, "2-point hat (trilinear), HemoCell's default"},
    DeltaKernel{"phi3", 3, phi3, "Roma-Peskin 3-point"},
    DeltaKernel{"phi4", 4, phi4, "Peskin standard 4-point"},
};

static_assert(std::ranges::all_of(kKernels,
                                  [](const DeltaKernel& kernel) {
                                    return kernel.support_width >= 1 &&
                                           kernel.support_width <= kMaxSupportWidth;
                                  }),
              "a registered kernel is wider than the stencil's fixed capacity");

}  // namespace

std::span<const DeltaKernel> delta_kernels() { return kKernels; }

const DeltaKernel& find_delta_kernel(std::string_view name) {
  return find_entry(kKernels, name, "ibm.kernel");
}

}  // namespace rbcsim::ibm
