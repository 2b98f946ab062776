#include "minimise/stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "minimise/vector_field.hpp"

namespace rbcsim::minimise {
namespace {

constexpr int kPowerIterations = 30;

// A fixed pseudo-random start vector (splitmix64), so the estimate is reproducible.
std::vector<Vec3> start_direction(std::size_t count) {
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&state] {
    state += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) / 9007199254740992.0 * 2.0 - 1.0;
  };
  std::vector<Vec3> direction(count);
  for (auto& component : direction) {
    // x, y, z in that order (a constructor's arguments are unsequenced).
    const double x = next();
    const double y = next();
    const double z = next();
    component = Vec3(x, y, z);
  }
  return direction;
}

}  // namespace

double estimate_stiffest_mode(const ForceField& forces, std::span<const Vec3> positions,
                              double probe_length) {
  const auto count = positions.size();
  std::vector<Vec3> base(count);
  forces(positions, base);
  auto direction = start_direction(count);
  std::vector<Vec3> probe(count);
  std::vector<Vec3> probed(count);
  double stiffness = 0.0;
  for (int iteration = 0; iteration < kPowerIterations; ++iteration) {
    const double length = norm(direction);
    for (auto& v : direction) v /= length;
    const double step = probe_length / max_norm(direction);
    for (std::size_t i = 0; i < count; ++i) probe[i] = positions[i] + step * direction[i];
    forces(probe, probed);
    for (std::size_t i = 0; i < count; ++i) direction[i] = (probed[i] - base[i]) / step;
    stiffness = norm(direction);
  }
  return stiffness;
}

}  // namespace rbcsim::minimise
