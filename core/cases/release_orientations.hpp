// The release orientations of a capillary ensemble (`rbcsim capillary --orientations N`): a
// deterministic, seeded set of N rigid rotations of the cell before the case turns its z axis
// onto capillary.cell_axis. Rotation k takes z to d_k, the k-th point of a Fibonacci lattice on
// the whole sphere from d_0 = z (the configured release itself) to d_{N-1} = -z, and then spins
// the cell about d_k by an angle drawn uniformly from [0, 2 pi) with the seed (spin_0 = 0). The
// whole sphere, not a hemisphere: a cup released mouth first is not a cup released bottom first.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "common/vec3.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::cases {

struct ReleaseOrientation {
  Vec3 axis;        // d_k: where the cell's z axis points
  double spin_rad;  // about d_k
  Eigen::Matrix3d rotation;
};

// Throws std::invalid_argument for count < 1.
std::vector<ReleaseOrientation> release_orientations(int count, std::uint64_t seed);

// The mesh rotated about the origin.
mesh::TriangleMesh rotated(mesh::TriangleMesh mesh, const Eigen::Matrix3d& rotation);

// Mean, sample standard deviation (n - 1), smallest and largest of the values; zeros for none,
// standard deviation 0 for one.
struct Spread {
  std::size_t count = 0;
  double mean = 0.0;
  double standard_deviation = 0.0;
  double min = 0.0;
  double max = 0.0;
};
Spread spread_of(const std::vector<double>& values);

}  // namespace rbcsim::cases
