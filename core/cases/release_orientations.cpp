#include "cases/release_orientations.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace rbcsim::cases {

std::vector<ReleaseOrientation> release_orientations(int count, std::uint64_t seed) {
  if (count < 1) throw std::invalid_argument("release_orientations: count must be >= 1");
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> spin(0.0, 2.0 * std::numbers::pi);
  std::vector<ReleaseOrientation> orientations;
  for (int k = 0; k < count; ++k) {
    const double z = count == 1 ? 1.0 : 1.0 - 2.0 * k / (count - 1.0);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden_angle * k;
    const Vec3 axis(r * std::cos(phi), r * std::sin(phi), z);
    const double spin_rad = k == 0 ? 0.0 : spin(generator);
    const Eigen::Matrix3d tilt =
        Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axis).toRotationMatrix();
    orientations.push_back(
        {axis, spin_rad, Eigen::AngleAxisd(spin_rad, axis).toRotationMatrix() * tilt});
  }
  return orientations;
}

mesh::TriangleMesh rotated(mesh::TriangleMesh mesh, const Eigen::Matrix3d& rotation) {
  for (auto& position : mesh.positions_um) position = rotation * position;
  return mesh;
}

Spread spread_of(const std::vector<double>& values) {
  Spread spread;
  spread.count = values.size();
  if (values.empty()) return spread;
  double sum = 0.0;
  for (double v : values) sum += v;
  spread.mean = sum / static_cast<double>(values.size());
  double squares = 0.0;
  for (double v : values) squares += (v - spread.mean) * (v - spread.mean);
  if (values.size() > 1) {
    spread.standard_deviation = std::sqrt(squares / static_cast<double>(values.size() - 1));
  }
  spread.min = *std::min_element(values.begin(), values.end());
  spread.max = *std::max_element(values.begin(), values.end());
  return spread;
}

}  // namespace rbcsim::cases
