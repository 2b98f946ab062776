// Membrane viscosity as edge friction (membrane/edge_friction.hpp) against continuum theory: on a
// flat triangular patch moving with a uniform velocity gradient, the dissipated power per area is
// that of a 2D Newtonian membrane of shear viscosity eta_m (simple shear) and, with the central
// split, dilatational viscosity 2 eta_m; a rigid motion dissipates nothing (central) or damps the
// rotation (Fedosov's tangential friction). Then the forces' conservation laws on a cell and the
// implicit step of the coupling.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "membrane/edge_friction.hpp"
#include "membrane/force_terms.hpp"
#include "membrane/membrane_model.hpp"
#include "test_shapes.hpp"

namespace {

using rbcsim::Vec3;
namespace membrane = rbcsim::membrane;

// A flat hexagonal patch of `rings` rings of equilateral triangles (edge `edge_um`), in the plane
// spanned by the orthonormal `first` and `second` directions: 3 n^2 + n edges along each of the
// three lattice directions.
struct Patch {
  std::vector<Vec3> positions;
  std::vector<rbcsim::mesh::Edge> edges;
  std::vector<std::int32_t> offsets;
  std::vector<std::int32_t> vertex_edges;
  double edge_um = 0.0;
  membrane::EdgeNetwork network() const { return {edges, offsets, vertex_edges}; }
  // The Voronoi share of the plane per edge, l^2 / (2 sqrt3), times the edges: a periodic
  // lattice's area, without the patch's boundary error.
  double effective_area_um2() const {
    return static_cast<double>(edges.size()) * edge_um * edge_um / (2.0 * std::numbers::sqrt3);
  }
};

Patch hexagonal_patch(int rings, double edge_um, const Vec3& first, const Vec3& second) {
  Patch patch;
  patch.edge_um = edge_um;
  std::vector<std::pair<int, int>> lattice;
  auto index_of = [&](int i, int j) -> int {
    for (std::size_t k = 0; k < lattice.size(); ++k) {
      if (lattice[k] == std::make_pair(i, j)) return static_cast<int>(k);
    }
    return -1;
  };
  for (int j = -rings; j <= rings; ++j) {
    for (int i = -rings; i <= rings; ++i) {
      if (std::abs(i + j) > rings) continue;
      lattice.emplace_back(i, j);
      patch.positions.push_back(edge_um * ((i + 0.5 * j) * first + (0.5 * std::numbers::sqrt3 * j) * second));
    }
  }
  const std::pair<int, int> directions[3] = {{1, 0}, {0, 1}, {-1, 1}};
  for (std::size_t k = 0; k < lattice.size(); ++k) {
    for (const auto& [di, dj] : directions) {
      const int other = index_of(lattice[k].first + di, lattice[k].second + dj);
      if (other >= 0) patch.edges.push_back({static_cast<std::int32_t>(k), other, -1, -1, -1, -1});
    }
  }
  patch.offsets.assign(patch.positions.size() + 1, 0);
  for (const auto& edge : patch.edges) {
    ++patch.offsets[edge.vertex0 + 1];
    ++patch.offsets[edge.vertex1 + 1];
  }
  for (std::size_t v = 0; v < patch.positions.size(); ++v) patch.offsets[v + 1] += patch.offsets[v];
  patch.vertex_edges.resize(2 * patch.edges.size());
  auto next = patch.offsets;
  for (std::size_t e = 0; e < patch.edges.size(); ++e) {
    patch.vertex_edges[next[patch.edges[e].vertex0]++] = static_cast<std::int32_t>(e);
    patch.vertex_edges[next[patch.edges[e].vertex1]++] = static_cast<std::int32_t>(e);
  }
  return patch;
}

// -sum F . v of the production forces at v_i = G x_i (G in the patch's frame, as a 3D map).
double dissipated_power(const Patch& patch, const Eigen::Matrix3d& gradient,
                        const membrane::EdgeFrictionParameters& friction) {
  std::vector<Vec3> velocities;
  for (const auto& x : patch.positions) velocities.push_back(gradient * x);
  std::vector<Vec3> forces(patch.positions.size());
  membrane::edge_friction_forces(patch.positions, velocities, patch.network(), friction, forces);
  double power = 0.0;
  for (std::size_t v = 0; v < forces.size(); ++v) power -= forces[v].dot(velocities[v]);
  return power;
}

// The patch tilted out of the x-y plane, so no coordinate axis is special.
const Vec3 kFirst = Vec3(1.0, 1.0, 1.0).normalized();
const Vec3 kSecond = Vec3(1.0, -1.0, 0.0).normalized();
Eigen::Matrix3d in_plane(double gxx, double gxy, double gyx, double gyy) {
  return gxx * kFirst * kFirst.transpose() + gxy * kFirst * kSecond.transpose() +
         gyx * kSecond * kFirst.transpose() + gyy * kSecond * kSecond.transpose();
}

TEST(EdgeFriction, SimpleShearDissipatesAsAMembraneOfViscosityEtaM) {
  const double eta_Pa_s_um = 0.5;
  const double rate_per_s = 200.0;
  const auto patch = hexagonal_patch(6, 0.25, kFirst, kSecond);
  for (const auto& split : membrane::viscosity_splits().entries()) {
    SCOPED_TRACE(std::string(split.name));
    const auto friction = split.split(eta_Pa_s_um);
    // v_first = rate * x_second: a 2D Newtonian membrane dissipates eta rate^2 per area.
    const double power = dissipated_power(patch, in_plane(0.0, rate_per_s, 0.0, 0.0), friction);
    EXPECT_NEAR(power / patch.effective_area_um2(), eta_Pa_s_um * rate_per_s * rate_per_s,
                1e-12 * eta_Pa_s_um * rate_per_s * rate_per_s);
  }
}

TEST(EdgeFrictionCentral, DilationDissipatesAtTwiceTheShearViscosityAndRigidMotionNothing) {
  const double eta_Pa_s_um = 0.5;
  const auto friction = membrane::edge_friction_for(eta_Pa_s_um, "central");
  EXPECT_EQ(friction.tangential_pN_s_per_um, 0.0);
  const auto patch = hexagonal_patch(5, 0.3, kFirst, kSecond);
  const double rate = 50.0;
  // Isotropic dilation v = s x: zeta (tr D)^2 = 2 eta (2 s)^2 per area.
  EXPECT_NEAR(dissipated_power(patch, in_plane(rate, 0.0, 0.0, rate), friction) /
                  patch.effective_area_um2(),
              8.0 * eta_Pa_s_um * rate * rate, 1e-9 * eta_Pa_s_um * rate * rate);
  // Pure shear v = s (x, -y): 2 eta D:D = 4 eta s^2 per area.
  EXPECT_NEAR(dissipated_power(patch, in_plane(rate, 0.0, 0.0, -rate), friction) /
                  patch.effective_area_um2(),
              4.0 * eta_Pa_s_um * rate * rate, 1e-9 * eta_Pa_s_um * rate * rate);
  // A rigid rotation in the plane and one about an in-plane axis: no dissipation.
  EXPECT_NEAR(dissipated_power(patch, in_plane(0.0, -rate, rate, 0.0), friction), 0.0, 1e-9);
  const Vec3 normal = kFirst.cross(kSecond);
  const Eigen::Matrix3d tilt = rate * (normal * kFirst.transpose() - kFirst * normal.transpose());
  EXPECT_NEAR(dissipated_power(patch, tilt, friction), 0.0, 1e-9);
}

TEST(EdgeFrictionFedosov, TangentialFrictionDampsARigidRotation) {
  // The price of Fedosov's split: 2 sqrt3 gamma_T omega^2 per area under a rigid rotation.
  const auto friction = membrane::edge_friction_for(0.5, "fedosov");
  EXPECT_NEAR(friction.central_pN_s_per_um, friction.tangential_pN_s_per_um / 3.0, 1e-15);
  const auto patch = hexagonal_patch(5, 0.3, kFirst, kSecond);
  const double omega = 40.0;
  EXPECT_NEAR(dissipated_power(patch, in_plane(0.0, -omega, omega, 0.0), friction) /
                  patch.effective_area_um2(),
              2.0 * std::numbers::sqrt3 * friction.tangential_pN_s_per_um * omega * omega,
              1e-9 * omega * omega);
}

std::vector<Vec3> random_velocities(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> draw(-100.0, 100.0);
  std::vector<Vec3> velocities(count);
  for (auto& v : velocities) v = rbcsim::random_vec3(draw, generator);
  return velocities;
}

TEST(EdgeFriction, OnACellTheForcesSumToZeroAndTheCentralOnesHaveNoTorque) {
  const auto cell = rbcsim::membrane_test::ellipsoid(3, Vec3(4.0, 3.0, 1.5));
  const auto topology = rbcsim::mesh::MeshTopology::build(cell);
  const auto velocities = random_velocities(cell.vertex_count(), 3);
  for (const auto& split : membrane::viscosity_splits().entries()) {
    SCOPED_TRACE(std::string(split.name));
    const auto friction = split.split(0.5);
    std::vector<Vec3> forces(cell.vertex_count());
    membrane::edge_friction_forces(cell.positions_um, velocities,
                                   membrane::EdgeNetwork::of(topology), friction, forces);
    Vec3 total = Vec3::Zero();
    Vec3 torque = Vec3::Zero();
    double scale = 0.0;
    for (std::size_t v = 0; v < forces.size(); ++v) {
      total += forces[v];
      torque += cell.positions_um[v].cross(forces[v]);
      scale += forces[v].norm();
    }
    EXPECT_LT(total.norm(), 1e-12 * scale);
    if (split.name == "central") {
      EXPECT_LT(torque.norm(), 1e-12 * scale * 4.0);
    }
    // Never negative: friction only takes energy out.
    EXPECT_GT(membrane::edge_friction_power(cell.positions_um, velocities,
                                            membrane::EdgeNetwork::of(topology), friction),
              0.0);
  }
}

TEST(EdgeFriction, TheViscosityTermIsTheFrictionAtTheGivenVelocitiesAndNoneAtRest) {
  const auto cell = rbcsim::membrane_test::ellipsoid(2, Vec3(4.0, 3.0, 1.5));
  membrane::MembraneParameters parameters;
  parameters.forces = {"link", "viscosity"};
  const membrane::MembraneModel model(cell, parameters);
  EXPECT_TRUE(model.has_dissipative_terms());
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  model.compute(cell.positions_um, workspace, forces);  // at rest
  for (const auto& force : forces.term("viscosity").forces_pN) EXPECT_EQ(force, Vec3::Zero());
  const auto at_rest = forces.total_pN;
  const auto velocities = random_velocities(cell.vertex_count(), 5);
  model.compute(cell.positions_um, velocities, workspace, forces);
  std::vector<Vec3> expected(cell.vertex_count());
  membrane::edge_friction_forces(cell.positions_um, velocities,
                                 membrane::EdgeNetwork::of(model.topology()),
                                 membrane::edge_friction_for(0.5, "central"), expected);
  EXPECT_EQ(forces.term("viscosity").forces_pN, expected);
  EXPECT_EQ(forces.term("viscosity").energy_pN_um, 0.0);
  for (std::size_t v = 0; v < expected.size(); ++v) {
    EXPECT_EQ(forces.total_pN[v], at_rest[v] + expected[v]);  // added after the cap
  }
}

// The operator the coupling's implicit step uses (precomputed axes, edge by edge) is the
// friction force with the sign turned, and its diagonal blocks are those of the operator.
TEST(EdgeFriction, TheImplicitStepsOperatorIsMinusTheFrictionForce) {
  const auto cell = rbcsim::membrane_test::ellipsoid(3, Vec3(4.0, 3.0, 1.5));
  const auto topology = rbcsim::mesh::MeshTopology::build(cell);
  const auto network = membrane::EdgeNetwork::of(topology);
  const auto velocities = random_velocities(cell.vertex_count(), 9);
  for (const auto& split : membrane::viscosity_splits().entries()) {
    SCOPED_TRACE(std::string(split.name));
    const auto friction = split.split(0.5);
    std::vector<Vec3> forces(cell.vertex_count());
    membrane::edge_friction_forces(cell.positions_um, velocities, network, friction, forces);
    const auto axes = membrane::edge_axes(cell.positions_um, network);
    std::vector<Vec3> resistance(cell.vertex_count(), Vec3::Zero());
    membrane::add_friction_resistance(axes, velocities, network, friction, resistance);
    for (std::size_t v = 0; v < forces.size(); ++v) {
      EXPECT_LT((resistance[v] + forces[v]).norm(), 1e-12 * (1.0 + forces[v].norm()));
    }
    // Diagonal block of vertex 0: the operator applied to a velocity of vertex 0 alone.
    std::vector<Eigen::Matrix3d> blocks(cell.vertex_count(), Eigen::Matrix3d::Zero());
    membrane::add_friction_diagonal(axes, network, friction, blocks);
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<Vec3> unit(cell.vertex_count(), Vec3::Zero());
      unit[0][axis] = 1.0;
      std::vector<Vec3> column(cell.vertex_count(), Vec3::Zero());
      membrane::add_friction_resistance(axes, unit, network, friction, column);
      EXPECT_LT((column[0] - blocks[0].col(axis)).norm(), 1e-12);
    }
  }
}

}  // namespace
