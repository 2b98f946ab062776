#include "lattice/lees_edwards.hpp"

#include <cmath>

namespace rbcsim::lattice {

double lees_edwards_offset(double velocity_difference, std::size_t time, int nx) {
  const double offset = std::fmod(velocity_difference * static_cast<double>(time), nx);
  return offset < 0.0 ? offset + nx : offset;
}

std::array<LeesEdwardsPlane, 2> lees_edwards_planes(int ny, double offset,
                                                    double velocity_difference) {
  return {LeesEdwardsPlane{+1, 0, ny - 1, offset, -velocity_difference},
          LeesEdwardsPlane{-1, ny - 1, 0, -offset, velocity_difference}};
}

LeesEdwardsSource lees_edwards_source(int x, int cx, double displacement, int nx) {
  const double position = x - cx + displacement;
  const double low = std::floor(position);
  const int x_low = LatticeGrid::wrap(static_cast<int>(low), nx);
  return {x_low, LatticeGrid::wrap(x_low + 1, nx), position - low};
}

}  // namespace rbcsim::lattice
