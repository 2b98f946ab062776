// The volume hold of a coupled run (coupling/volume_hold.hpp): it leaves a rigid motion alone,
// takes out exactly the velocity along the volume gradient that changes the enclosed volume, and
// so keeps the volume of a cell moved through a compressing, shearing flow to second order in the
// step, where the flow alone changes it at first order.
#include "coupling/volume_hold.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "coupling_fixtures.hpp"
#include "mesh/geometry.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::coupling {
namespace {

using testing::sphere_mesh;

// The volume the mesh's own measure gives (mesh/geometry.hpp), at other positions.
double enclosed_volume(std::span<const Vec3> positions, std::span<const mesh::Triangle> triangles) {
  return mesh::enclosed_volume_um3(
      {std::vector<Vec3>(positions.begin(), positions.end()),
       std::vector<mesh::Triangle>(triangles.begin(), triangles.end())});
}

// An oblate, off-centre ellipsoid, so that no symmetry hides an error.
mesh::TriangleMesh ellipsoid() {
  auto mesh = sphere_mesh(3, 1.0, Vec3::Zero());
  for (Vec3& x : mesh.positions_um)
    x = Vec3(3.9 * x.x() + 11.0, 3.9 * x.y() - 4.0, 1.3 * x.z() + 7.5);
  return mesh;
}

TEST(VolumeHold, LeavesARigidMotionAlone) {
  const auto mesh = ellipsoid();
  const auto topology = mesh::MeshTopology::build(mesh);
  VolumeHold hold(mesh.triangles, topology);
  const Vec3 translation(0.02, -0.01, 0.005), omega(0.001, -0.002, 0.003), centre(2.0, 1.0, -3.0);
  std::vector<Vec3> velocities(mesh.vertex_count());
  for (std::size_t v = 0; v < velocities.size(); ++v) {
    velocities[v] = translation + omega.cross(mesh.positions_um[v] - centre);
  }
  const auto before = velocities;
  const double rate = hold.apply(mesh.positions_um, velocities);
  // A rigid motion's volume rate is zero: round-off of sums of 642 terms of ~0.1 um^3 per step.
  EXPECT_LT(std::abs(rate), 1e-13);
  for (std::size_t v = 0; v < velocities.size(); ++v) {
    EXPECT_LT((velocities[v] - before[v]).norm(), 1e-14) << "vertex " << v;
  }
}

TEST(VolumeHold, KeepsTheVolumeOfACellInACompressingShearFlow) {
  const auto mesh = ellipsoid();
  const auto topology = mesh::MeshTopology::build(mesh);
  VolumeHold hold(mesh.triangles, topology);
  // A simple shear plus a uniaxial compression with nothing to balance it: div u = -0.003.
  std::vector<Vec3> velocities(mesh.vertex_count());
  for (std::size_t v = 0; v < velocities.size(); ++v) {
    const Vec3& x = mesh.positions_um[v];
    velocities[v] = Vec3(0.01 * x.z() - 0.003 * (x.x() - 11.0), 0.0, 0.0);
  }
  const auto before = velocities;
  const double volume = enclosed_volume(mesh.positions_um, mesh.triangles);
  const double rate = hold.apply(mesh.positions_um, velocities);
  // The rate removed is the flow's: -0.003 times the enclosed volume (the divergence theorem,
  // exact for a velocity linear in x on a closed polyhedron).
  EXPECT_NEAR(rate, -0.003 * volume, 1e-12 * volume);
  // What it took out lies along the volume gradient: one multiple for every vertex.
  std::vector<Vec3> gradient(mesh.vertex_count(), Vec3::Zero());
  for (const auto& t : mesh.triangles) {
    const auto& x = mesh.positions_um;
    gradient[t[0]] += x[t[1]].cross(x[t[2]]) / 6.0;
    gradient[t[1]] += x[t[2]].cross(x[t[0]]) / 6.0;
    gradient[t[2]] += x[t[0]].cross(x[t[1]]) / 6.0;
  }
  double multiple_sum = 0.0, squared = 0.0;
  for (std::size_t v = 0; v < gradient.size(); ++v) {
    multiple_sum += (before[v] - velocities[v]).dot(gradient[v]);
    squared += gradient[v].squaredNorm();
  }
  const double multiple = multiple_sum / squared;
  for (std::size_t v = 0; v < gradient.size(); ++v) {
    EXPECT_LT((before[v] - velocities[v] - multiple * gradient[v]).norm(), 1e-15) << "vertex " << v;
  }
  // Moved for a step h, the volume changes by O(h^2) with the hold and by h * rate without.
  for (const double h : {1.0, 0.1}) {
    std::vector<Vec3> held(mesh.positions_um), free(mesh.positions_um);
    for (std::size_t v = 0; v < held.size(); ++v) {
      held[v] += h * velocities[v];
      free[v] += h * before[v];
    }
    const double held_change = enclosed_volume(held, mesh.triangles) - volume;
    const double free_change = enclosed_volume(free, mesh.triangles) - volume;
    EXPECT_NEAR(free_change, h * rate, 0.01 * std::abs(h * rate)) << "h " << h;
    // The second-order remainder: at most (h |u|_max / size)^2 of the volume, 1e-4 at h = 1.
    EXPECT_LT(std::abs(held_change), 1e-4 * h * h * volume) << "h " << h;
  }
}

}  // namespace
}  // namespace rbcsim::coupling
