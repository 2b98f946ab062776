// The D3Q19 velocity set (Qian, d'Humieres & Lallemand 1992) in lattice units (dx = dt = 1).
// Directions come in opposite pairs: 2k-1 and 2k are opposite for k = 1..9, so that kernels can
// relax a pair at once (TRT) and bounce-back is a table look-up.
#pragma once

#include <array>

namespace rbcsim::lattice {

inline constexpr int kDirections = 19;

inline constexpr std::array<std::array<int, 3>, kDirections> kVelocities = {{
    {0, 0, 0},                                                              // rest
    {1, 0, 0}, {-1, 0, 0},  {0, 1, 0},  {0, -1, 0}, {0, 0, 1}, {0, 0, -1},  // faces
    {1, 1, 0}, {-1, -1, 0}, {1, -1, 0}, {-1, 1, 0},                         // xy edges
    {1, 0, 1}, {-1, 0, -1}, {1, 0, -1}, {-1, 0, 1},                         // xz edges
    {0, 1, 1}, {0, -1, -1}, {0, 1, -1}, {0, -1, 1},                         // yz edges
}};

inline constexpr double kWeightRest = 1.0 / 3.0;
inline constexpr double kWeightFace = 1.0 / 18.0;
inline constexpr double kWeightEdge = 1.0 / 36.0;

inline constexpr std::array<double, kDirections> kWeights = {
    kWeightRest, kWeightFace, kWeightFace, kWeightFace, kWeightFace, kWeightFace, kWeightFace,
    kWeightEdge, kWeightEdge, kWeightEdge, kWeightEdge, kWeightEdge, kWeightEdge, kWeightEdge,
    kWeightEdge, kWeightEdge, kWeightEdge, kWeightEdge, kWeightEdge};

inline constexpr std::array<int, kDirections> kOpposite = {0, 2,  1,  4,  3,  6,  5,  8,  7, 10,
                                                           9, 12, 11, 14, 13, 16, 15, 18, 17};

// Speed of sound squared, c_s^2 = 1/3, and the inverse powers the equilibrium needs.
inline constexpr double kSoundSpeedSquared = 1.0 / 3.0;
inline constexpr double kInverseSoundSpeedSquared = 3.0;
inline constexpr double kHalfInverseSoundSpeedFourth = 4.5;

// c_i . v for a lattice direction i and a vector v.
constexpr double dot_velocity(int direction, const std::array<double, 3>& vector) {
  const auto& c = kVelocities[direction];
  return c[0] * vector[0] + c[1] * vector[1] + c[2] * vector[2];
}

// Second-order equilibrium f_i^eq = w_i rho (1 + c.u/c_s^2 + (c.u)^2/(2 c_s^4) - u.u/(2 c_s^2)).
constexpr double equilibrium(int direction, double density, const std::array<double, 3>& velocity) {
  const double cu = dot_velocity(direction, velocity);
  const double uu =
      velocity[0] * velocity[0] + velocity[1] * velocity[1] + velocity[2] * velocity[2];
  return kWeights[direction] * density *
         (1.0 + kInverseSoundSpeedSquared * cu + kHalfInverseSoundSpeedFourth * cu * cu -
          0.5 * kInverseSoundSpeedSquared * uu);
}

}  // namespace rbcsim::lattice
