// The implicit membrane friction of a coupled run (coupling/membrane_friction.hpp): one backward-
// Euler step of the edge friction on the fluid under a membrane conserves the fluid's momentum,
// only takes kinetic energy out, leaves a rigid motion alone, and at a stiff friction leaves the
// membrane's edges hardly stretching.
#include "coupling/membrane_friction.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "coupling_fixtures.hpp"
#include "ibm/delta_kernels.hpp"
#include "membrane/edge_friction.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::coupling {
namespace {

using testing::periodic_fluid;
using testing::sphere_mesh;

struct FrictionCase {
  std::unique_ptr<lattice::FluidSolver> fluid;
  mesh::TriangleMesh sphere;  // lattice units
  mesh::MeshTopology topology;
  ibm::InterpolationStencil stencil;
};

// A 642-vertex sphere of radius 4.5 dx in a periodic 24^3 box whose fluid moves with
// u = u0 (sin(2 pi y / 24), 0, cos(2 pi x / 24)) (plus `rigid` everywhere): a flow that stretches
// and shears the membrane.
FrictionCase make_case(const Vec3& rigid) {
  const int n = 24;
  auto fluid = periodic_fluid(n, n, n);
  const std::size_t nodes = fluid->grid().node_count();
  lattice::VectorField velocity{std::vector<double>(nodes), std::vector<double>(nodes),
                                std::vector<double>(nodes)};
  const double two_pi = 2.0 * std::acos(-1.0);
  for (std::size_t node = 0; node < nodes; ++node) {
    const auto c = fluid->grid().coordinates(node);
    velocity[0][node] = rigid.x() + 0.01 * std::sin(two_pi * c[1] / n);
    velocity[1][node] = rigid.y();
    velocity[2][node] = rigid.z() + 0.01 * std::cos(two_pi * c[0] / n);
  }
  fluid->initialise_equilibrium(std::vector<double>(nodes, 1.0), velocity);
  auto sphere = sphere_mesh(3, 4.5, Vec3::Constant(0.5 * (n - 1)));
  auto topology = mesh::MeshTopology::build(sphere);
  ibm::InterpolationStencil stencil;
  stencil.build(ibm::find_delta_kernel("phi2"), {n, n, n, true, true, true}, sphere.positions_um);
  return {std::move(fluid), std::move(sphere), std::move(topology), std::move(stencil)};
}

Vec3 total_momentum(const lattice::FluidSolver& fluid) {
  const auto populations = fluid.pre_collision_populations();
  const std::size_t nodes = fluid.grid().node_count();
  Vec3 sum = Vec3::Zero();
  for (int i = 0; i < lattice::kDirections; ++i) {
    const auto& c = lattice::kVelocities[i];
    for (std::size_t node = 0; node < nodes; ++node) {
      sum += populations[static_cast<std::size_t>(i) * nodes + node] * Vec3(c[0], c[1], c[2]);
    }
  }
  return sum;
}

double kinetic_energy(const lattice::FluidSolver& fluid) {
  double sum = 0.0;
  for (std::size_t node = 0; node < fluid.grid().node_count(); ++node) {
    const Vec3 u(fluid.velocity()[0][node], fluid.velocity()[1][node], fluid.velocity()[2][node]);
    sum += 0.5 * fluid.density()[node] * u.squaredNorm();
  }
  return sum;
}

// Sum over edges of |edge stretching rate| of vertex velocities.
double stretching(const FrictionCase& c, std::span<const Vec3> velocities) {
  double sum = 0.0;
  for (const auto& edge : c.topology.edges()) {
    const Vec3 axis =
        (c.sphere.positions_um[edge.vertex0] - c.sphere.positions_um[edge.vertex1]).normalized();
    sum += std::abs((velocities[edge.vertex0] - velocities[edge.vertex1]).dot(axis));
  }
  return sum;
}

std::vector<Vec3> interpolated(const FrictionCase& c) {
  std::vector<Vec3> velocities(c.sphere.vertex_count());
  for (std::size_t v = 0; v < velocities.size(); ++v) {
    Vec3 sum = Vec3::Zero();
    const auto nodes = c.stencil.nodes(v);
    const auto weights = c.stencil.weights(v);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const auto u = c.fluid->velocity_at(nodes[k]);
      sum += weights[k] * Vec3(u[0], u[1], u[2]);
    }
    velocities[v] = sum;
  }
  return velocities;
}

TEST(ImplicitMembraneFriction, ConservesMomentumAndOnlyTakesEnergyOut) {
  auto c = make_case(Vec3(0.02, -0.01, 0.005));
  const Vec3 momentum_before = total_momentum(*c.fluid);
  const double energy_before = kinetic_energy(*c.fluid);
  const double stretching_before = stretching(c, interpolated(c));
  // The red cell's membrane viscosity at the paper's lattice: gamma_C ~ 340 lattice units.
  const auto friction = membrane::edge_friction_for(340.0, "central");
  std::vector<Vec3> membrane_velocities(c.sphere.vertex_count());
  ImplicitMembraneFriction step;
  const auto iterations =
      step.apply(c.stencil, c.sphere.positions_um, membrane::EdgeNetwork::of(c.topology), friction,
                 2.0, *c.fluid, membrane_velocities);
  EXPECT_GT(iterations, 0u);
  const Vec3 change = total_momentum(*c.fluid) - momentum_before;
  EXPECT_LT(change.norm(), 1e-13 * momentum_before.norm()) << change.transpose();
  EXPECT_LT(kinetic_energy(*c.fluid), energy_before);
  // Stiff friction: the membrane's edges now hardly stretch, in the fluid it moves with.
  EXPECT_LT(stretching(c, interpolated(c)), 0.05 * stretching_before);
  EXPECT_LT(stretching(c, membrane_velocities), 0.05 * stretching_before);
}

TEST(ImplicitMembraneFriction, LeavesARigidMotionAlone) {
  const int n = 24;
  auto c = make_case(Vec3::Zero());
  // Replace the flow by a rigid translation plus a rotation about the sphere's centre.
  const std::size_t nodes = c.fluid->grid().node_count();
  lattice::VectorField velocity{std::vector<double>(nodes), std::vector<double>(nodes),
                                std::vector<double>(nodes)};
  const Vec3 centre = Vec3::Constant(0.5 * (n - 1));
  const Vec3 omega(0.0, 0.0, 0.001);
  for (std::size_t node = 0; node < nodes; ++node) {
    const auto x = c.fluid->grid().coordinates(node);
    const Vec3 u = Vec3(0.01, 0.0, 0.0) + omega.cross(Vec3(x[0], x[1], x[2]) - centre);
    for (int axis = 0; axis < 3; ++axis) velocity[axis][node] = u[axis];
  }
  c.fluid->initialise_equilibrium(std::vector<double>(nodes, 1.0), velocity);
  const auto before = c.fluid->velocity();
  std::vector<Vec3> membrane_velocities(c.sphere.vertex_count());
  ImplicitMembraneFriction step;
  step.apply(c.stencil, c.sphere.positions_um, membrane::EdgeNetwork::of(c.topology),
             membrane::edge_friction_for(340.0, "central"), 2.0, *c.fluid, membrane_velocities);
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t node = 0; node < nodes; ++node) {
      EXPECT_NEAR(c.fluid->velocity()[axis][node], before[axis][node], 1e-12);
    }
  }
}

// Each solve starts from the previous one's correction u' - u: the same problem solved again starts
// at its solution, needs no iteration and gives the same membrane velocities.
TEST(ImplicitMembraneFriction, StartsFromThePreviousCorrection) {
  auto c = make_case(Vec3(0.02, -0.01, 0.005));
  const auto friction = membrane::edge_friction_for(340.0, "central");
  const auto network = membrane::EdgeNetwork::of(c.topology);
  std::vector<Vec3> first(c.sphere.vertex_count()), again(c.sphere.vertex_count());
  ImplicitMembraneFriction step;
  // solve only reads the fluid: both solves see the same state.
  const auto cold =
      step.solve(c.stencil, c.sphere.positions_um, network, friction, 2.0, *c.fluid, first);
  const auto warm =
      step.solve(c.stencil, c.sphere.positions_um, network, friction, 2.0, *c.fluid, again);
  EXPECT_GT(cold, 10u);
  EXPECT_EQ(warm, 0u);
  double largest = 0.0;
  for (const Vec3& v : first) largest = std::max(largest, v.norm());
  for (std::size_t v = 0; v < first.size(); ++v) {
    EXPECT_LT((again[v] - first[v]).norm(), 1e-12 * largest) << "vertex " << v;
  }
}

}  // namespace
}  // namespace rbcsim::coupling
