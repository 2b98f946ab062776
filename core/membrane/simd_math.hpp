// Math for loops that the compiler vectorises across elements (the optimised kernel's passes):
// a plain three-double vector and an atan2 without a library call. Eigen objects and calls into
// libm both keep GCC from vectorising such a loop (Eigen temporaries live in memory; a call
// cannot be widened), so the passes use these instead.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

// The passes are compiled for the baseline x86-64 and for AVX2 and AVX-512 machines; the loader
// picks the best clone the CPU supports, so the binary stays portable.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RBCSIM_MEMBRANE_VECTOR_CLONES \
  __attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#else
#define RBCSIM_MEMBRANE_VECTOR_CLONES
#endif

namespace rbcsim::membrane::simd {

// `value` where `on` is nonzero, else 0 (not 0 * value, which is NaN for an infinite value). A
// switch is a double rather than a bool because GCC vectorises a select on a compared double.
inline double where(double on, double value) { return on != 0.0 ? value : 0.0; }

struct Xyz {
  double x;
  double y;
  double z;
};

inline Xyz operator+(const Xyz& a, const Xyz& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Xyz operator-(const Xyz& a, const Xyz& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Xyz operator*(double s, const Xyz& a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(const Xyz& a, const Xyz& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Xyz cross(const Xyz& a, const Xyz& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Point `index` of an array of x, y, z triples (std::vector<Vec3>::data()).
inline Xyz load(const double* xyz, std::int32_t index) {
  const std::int32_t first = 3 * index;
  return {xyz[first], xyz[first + 1], xyz[first + 2]};
}

// Where Xyz values go: one array per component.
struct XyzArrays {
  double* x;
  double* y;
  double* z;
  void store(std::size_t i, const Xyz& v) const {
    x[i] = v.x;
    y[i] = v.y;
    z[i] = v.z;
  }
  Xyz load(std::size_t i) const { return {x[i], y[i], z[i]}; }
  // v where `on` is nonzero, else zero (see where()).
  void store_where(std::size_t i, const Xyz& v, double on) const {
    x[i] = where(on, v.x);
    y[i] = where(on, v.y);
    z[i] = where(on, v.z);
  }
};

// atan2(y, x) in (-pi, pi], within a few ulp of std::atan2 (tested), branch-free. Reduction:
// t = min(|x|, |y|) / max(|x|, |y|) in [0, 1]; above tan(pi/8), atan t = pi/4 + atan((t-1)/(t+1)),
// so the series runs on |u| <= tan(pi/8) (u^2 <= 0.172), where 21 terms leave a relative
// truncation error below 1e-18. Then the octant is undone. (0, 0) gives 0.
inline double atan2(double y, double x) {
  const double ax = std::abs(x);
  const double ay = std::abs(y);
  const bool swapped = ay > ax;  // |angle from the x axis| > pi/4: use atan(x/y)
  const double numerator = swapped ? ax : ay;
  const double denominator = swapped ? ay : ax;
  const bool shifted = numerator > (std::numbers::sqrt2 - 1.0) * denominator;
  const double ratio = (shifted ? numerator - denominator : numerator) /
                       (shifted ? numerator + denominator : denominator);
  const double u = denominator > 0.0 ? ratio : 0.0;
  // atan u = u + u^3 q(u^2), q(s) = sum_{j=0}^{19} (-1)^(j+1) s^j / (2j + 3): the exact leading
  // term keeps the rounding of q small. q splits into its even and odd powers, two independent
  // Horner chains in u^4 (half the dependent steps of one chain in u^2).
  const double u2 = u * u;
  const double u4 = u2 * u2;
  double even = -1.0 / 39.0;  // j = 18
#pragma GCC unroll 9
  for (int j = 16; j >= 0; j -= 2) even = -1.0 / (2 * j + 3) + u4 * even;
  double odd = 1.0 / 41.0;  // j = 19
#pragma GCC unroll 9
  for (int j = 17; j >= 1; j -= 2) odd = 1.0 / (2 * j + 3) + u4 * odd;
  const double q = even + u2 * odd;
  double angle = (u + (u * u2) * q) + (shifted ? std::numbers::pi / 4 : 0.0);
  angle = swapped ? std::numbers::pi / 2 - angle : angle;
  angle = x < 0.0 ? std::numbers::pi - angle : angle;
  return std::copysign(angle, y);
}

inline double sign(double value) { return value > 0.0 ? 1.0 : (value < 0.0 ? -1.0 : 0.0); }

// The larger of a running maximum and |value|; NaN sticks (it must fail a limit check).
inline double max_magnitude(double largest, double value) {
  const double magnitude = std::abs(value);
  return (magnitude > largest || std::isnan(magnitude)) ? magnitude : largest;
}

}  // namespace rbcsim::membrane::simd
