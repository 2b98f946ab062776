// The implicit membrane friction of a coupled run (coupling/membrane_friction.hpp): one backward-
// Euler step of the edge friction on the fluid under a membrane conserves the fluid's momentum,
// only takes kinetic energy out, leaves a rigid motion alone, and at a stiff friction leaves the
// membrane's edges hardly stretching.
#include "coupling/membrane_friction.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "coupling_fixtures.hpp"
#include "ibm/delta_kernels.hpp"
#include "ibm/transfer.hpp"
#include "lattice/fluid_solver.hpp"
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

// A sphere (by default 642 vertices, radius 4.5 dx) in a periodic n^3 box (24^3) whose fluid
// moves with u = u0 (sin(2 pi y / n), 0, cos(2 pi x / n)) (plus `rigid` everywhere): a flow that
// stretches and shears the membrane.
FrictionCase make_case(const Vec3& rigid, int level = 3, double radius = 4.5, int n = 24) {
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
  auto sphere = sphere_mesh(level, radius, Vec3::Constant(0.5 * (n - 1)));
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
                 2.0, *c.fluid, {}, membrane_velocities);
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
             membrane::edge_friction_for(340.0, "central"), 2.0, *c.fluid, {}, membrane_velocities);
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t node = 0; node < nodes; ++node) {
      EXPECT_NEAR(c.fluid->velocity()[axis][node], before[axis][node], 1e-12);
    }
  }
}

// The membrane moves with the velocity the fluid's next collision sees, Guo's (m + F/2) / rho, not
// with m / rho: spread forces on the sphere and a body force, step the fluid, solve (no friction:
// u' = u), then spread the same forces again and step: the interpolation of that collision's
// velocity is what the solve gave the membrane. Without the half force they differ by F / (2 rho)
// (here 3e-4 against flows of 0.01).
TEST(ImplicitMembraneFriction, MovesTheMembraneWithTheNextCollisionsVelocity) {
  auto c = make_case(Vec3(0.02, -0.01, 0.005));
  const Vec3 body_force(2e-5, 0.0, -1e-5);
  std::vector<Vec3> forces(c.sphere.vertex_count());
  for (std::size_t v = 0; v < forces.size(); ++v) {
    // Inward, as a membrane's tension pulls, and varying over the sphere.
    const Vec3 outward = (c.sphere.positions_um[v] - Vec3::Constant(11.5)).normalized();
    forces[v] = -2e-4 * (1.0 + 0.5 * outward.x()) * outward;
  }
  lattice::FluidParameters parameters = c.fluid->parameters();
  parameters.body_force = {body_force.x(), body_force.y(), body_force.z()};
  auto fluid = std::make_unique<lattice::FluidSolver>(c.fluid->grid(), parameters);
  const std::size_t nodes = fluid->grid().node_count();
  fluid->initialise_equilibrium(std::vector<double>(nodes, 1.0), c.fluid->velocity());
  c.fluid = std::move(fluid);
  const ibm::GridView grid{24, 24, 24, true, true, true};
  auto spread_and_step = [&] {
    auto& density = c.fluid->force_density();
    ibm::spread_forces(c.stencil, forces, grid, density[0].data(), density[1].data(),
                       density[2].data());
    c.fluid->step();
  };
  spread_and_step();
  spread_and_step();  // the optimised kernel's populations are natural after every second step
  std::vector<Vec3> membrane_velocities(c.sphere.vertex_count());
  ImplicitMembraneFriction step;
  step.solve(c.stencil, c.sphere.positions_um, membrane::EdgeNetwork::of(c.topology), {}, 2.0,
             *c.fluid, {forces, body_force}, membrane_velocities);
  spread_and_step();
  const auto next = interpolated(c);
  double largest = 0.0;
  for (std::size_t v = 0; v < next.size(); ++v) {
    largest = std::max(largest, (membrane_velocities[v] - next[v]).norm());
  }
  EXPECT_LT(largest, 1e-12);
}

// A fluid at rest under a static force density F (here the spread of inward vertex forces, as a
// membrane's tension pulls against the pressure inside) has Guo's velocity (m + F/2) / rho = 0, its
// populations' momentum m = -F/2. The friction then has nothing to act on: the membrane stays at
// rest and no momentum is exchanged, at a stiff friction solved over one step or two. Solving on
// the populations' velocity m / rho instead, and adding F / (2 rho) to the membrane afterwards,
// fails here: the friction takes out the part of -F / (2 rho) that stretches the membrane, and the
// membrane moves inwards through a fluid at rest.
TEST(ImplicitMembraneFriction, LeavesAMembraneAtRestInAFluidAtRestUnderAStaticForce) {
  const int n = 24;
  auto c = make_case(Vec3::Zero());
  std::vector<Vec3> forces(c.sphere.vertex_count());
  for (std::size_t v = 0; v < forces.size(); ++v) {
    const Vec3 outward = (c.sphere.positions_um[v] - Vec3::Constant(0.5 * (n - 1))).normalized();
    forces[v] = -2e-4 * (1.0 + 0.5 * outward.x()) * outward;
  }
  const std::size_t nodes = c.fluid->grid().node_count();
  lattice::VectorField force{std::vector<double>(nodes), std::vector<double>(nodes),
                             std::vector<double>(nodes)};
  ibm::spread_forces(c.stencil, forces, {n, n, n, true, true, true}, force[0].data(),
                     force[1].data(), force[2].data());
  lattice::VectorField velocity = force;  // u = m / rho = -F / 2 at rho = 1
  for (auto& component : velocity) {
    for (double& value : component) value *= -0.5;
  }
  c.fluid->initialise_equilibrium(std::vector<double>(nodes, 1.0), velocity);
  const auto friction = membrane::edge_friction_for(340.0, "fedosov");
  for (const double dt : {1.0, 2.0}) {
    std::vector<Vec3> membrane_velocities(c.sphere.vertex_count(), Vec3::Ones());
    ImplicitMembraneFriction step;
    step.solve(c.stencil, c.sphere.positions_um, membrane::EdgeNetwork::of(c.topology), friction,
               dt, *c.fluid, {forces, Vec3::Zero()}, membrane_velocities);
    double fastest = 0.0, largest_exchange = 0.0;
    for (const Vec3& u : membrane_velocities) fastest = std::max(fastest, u.norm());
    for (const Vec3& m : step.momentum()) largest_exchange = std::max(largest_exchange, m.norm());
    // Against the half force, 1e-4 and more at the membrane: round-off of sums of a few dozen
    // terms of that size.
    EXPECT_LT(fastest, 1e-15) << "dt " << dt;
    EXPECT_LT(largest_exchange, 1e-15) << "dt " << dt;
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
      step.solve(c.stencil, c.sphere.positions_um, network, friction, 2.0, *c.fluid, {}, first);
  const auto warm =
      step.solve(c.stencil, c.sphere.positions_um, network, friction, 2.0, *c.fluid, {}, again);
  EXPECT_GT(cold, 10u);
  EXPECT_EQ(warm, 0u);
  double largest = 0.0;
  for (const Vec3& v : first) largest = std::max(largest, v.norm());
  for (std::size_t v = 0; v < first.size(); ++v) {
    EXPECT_LT((again[v] - first[v]).norm(), 1e-12 * largest) << "vertex " << v;
  }
}

// The fluid under the membrane speeding up steadily (u = (1 + n/2) u0 at solve n): the correction
// u' - u grows by the same amount each solve, so the start extrapolated from the last two solves
// is the third solve's solution to their tolerance, where the previous correction alone (the
// second solve's start) is a third of it short.
TEST(ImplicitMembraneFriction, ExtrapolatesItsStartFromTheLastTwoSolves) {
  auto c = make_case(Vec3::Zero());
  const auto friction = membrane::edge_friction_for(340.0, "central");
  const auto network = membrane::EdgeNetwork::of(c.topology);
  ImplicitMembraneFriction step;
  step.prepare(c.stencil);
  const std::vector<std::size_t> nodes(step.nodes().begin(), step.nodes().end());
  std::vector<double> density(nodes.size());
  std::vector<Vec3> momentum(nodes.size()), scaled(nodes.size());
  c.fluid->pre_collision_moments(nodes, density, momentum);
  std::vector<Vec3> velocities(c.sphere.vertex_count());
  std::vector<std::size_t> iterations;
  for (int n = 0; n < 3; ++n) {
    step.prepare(c.stencil);  // each step's solve follows its prepare(), as in a run
    for (std::size_t k = 0; k < nodes.size(); ++k) scaled[k] = (1.0 + 0.5 * n) * momentum[k];
    iterations.push_back(step.solve_with_moments(c.sphere.positions_um, network, friction, 2.0,
                                                 density, scaled, {}, velocities));
  }
  EXPECT_GT(iterations[1], 10u);
  EXPECT_LT(4 * iterations[2], iterations[1])
      << iterations[0] << ", " << iterations[1] << ", " << iterations[2];
}

// The backward-Euler step solved directly: (R + S^T K S) u' = R u assembled as a dense matrix over
// the stencil's nodes and factorised. The iterative solve must give the same membrane velocities
// S u' and the same momentum R (u' - u), to its tolerance.
TEST(ImplicitMembraneFriction, MatchesADirectSolveOfTheBackwardEulerStep) {
  auto c = make_case(Vec3(0.02, -0.01, 0.005), 2, 3.5, 16);
  const auto friction = membrane::edge_friction_for(340.0, "fedosov");
  const auto network = membrane::EdgeNetwork::of(c.topology);
  const double dt = 2.0;
  std::vector<std::size_t> nodes;
  for (std::size_t v = 0; v < c.sphere.vertex_count(); ++v) {
    const auto reached = c.stencil.nodes(v);
    nodes.insert(nodes.end(), reached.begin(), reached.end());
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const auto node_count = static_cast<Eigen::Index>(nodes.size());
  const auto vertex_count = static_cast<Eigen::Index>(c.sphere.vertex_count());
  std::vector<double> density(nodes.size());
  std::vector<Vec3> momentum(nodes.size());
  c.fluid->pre_collision_moments(nodes, density, momentum);
  // S (3V x 3N) and K (3V x 3V), column by column.
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(3 * vertex_count, 3 * node_count);
  for (Eigen::Index v = 0; v < vertex_count; ++v) {
    const auto reached = c.stencil.nodes(static_cast<std::size_t>(v));
    const auto weights = c.stencil.weights(static_cast<std::size_t>(v));
    for (std::size_t s = 0; s < reached.size(); ++s) {
      const auto k = std::lower_bound(nodes.begin(), nodes.end(), reached[s]) - nodes.begin();
      for (int a = 0; a < 3; ++a) S(3 * v + a, 3 * k + a) += weights[s];
    }
  }
  const auto axes = membrane::edge_axes(c.sphere.positions_um, network);
  Eigen::MatrixXd K(3 * vertex_count, 3 * vertex_count);
  std::vector<Vec3> unit(c.sphere.vertex_count()), column(c.sphere.vertex_count());
  for (Eigen::Index j = 0; j < 3 * vertex_count; ++j) {
    std::fill(unit.begin(), unit.end(), Vec3::Zero());
    unit[static_cast<std::size_t>(j / 3)][static_cast<int>(j % 3)] = 1.0;
    std::fill(column.begin(), column.end(), Vec3::Zero());
    membrane::add_friction_resistance(axes, unit, network, friction, column);
    for (Eigen::Index i = 0; i < vertex_count; ++i) {
      K.block<3, 1>(3 * i, j) = dt * column[static_cast<std::size_t>(i)];
    }
  }
  Eigen::VectorXd rho_u(3 * node_count), R = Eigen::VectorXd::Zero(3 * node_count);
  for (Eigen::Index k = 0; k < node_count; ++k) {
    rho_u.segment<3>(3 * k) = momentum[static_cast<std::size_t>(k)];
    R.segment<3>(3 * k).setConstant(density[static_cast<std::size_t>(k)]);
  }
  const Eigen::MatrixXd A = Eigen::MatrixXd(R.asDiagonal()) + S.transpose() * K * S;
  const Eigen::VectorXd u_new = A.ldlt().solve(rho_u);
  const Eigen::VectorXd membrane_expected = S * u_new;
  const Eigen::VectorXd momentum_expected = R.asDiagonal() * u_new - rho_u;

  // The solve stops at a residual r = R u - A u' of `tolerance` times the first (the friction at
  // u' = u). The error e of u' then obeys |e| <= |r| / lambda_min(A) <= |r| / min rho (A >= R),
  // and the membrane's velocities inherit it (the weights sum to 1). The momentum -S^T K S u'
  // errs by S^T K S e = -r - R e, at most |r| (1 + max rho / min rho). Both the solver's own
  // tolerance and the runs' default (membrane.viscosity_solve_tolerance).
  const Eigen::VectorXd u = rho_u.cwiseQuotient(R);
  const double first_residual = (S.transpose() * (K * (S * u))).norm();
  std::size_t previous_iterations = 0;
  for (const double tolerance : {1e-6, 1e-4}) {
    std::vector<Vec3> membrane_velocities(c.sphere.vertex_count());
    ImplicitMembraneFriction step;
    const auto iterations =
        step.solve(c.stencil, c.sphere.positions_um, network, friction, dt, *c.fluid, {},
                   membrane_velocities, {.relative_tolerance = tolerance});
    ASSERT_EQ(step.nodes().size(), nodes.size());
    double worst_velocity = 0.0, worst_momentum = 0.0;
    for (Eigen::Index v = 0; v < vertex_count; ++v) {
      worst_velocity = std::max(worst_velocity, (membrane_velocities[static_cast<std::size_t>(v)] -
                                                 Vec3(membrane_expected.segment<3>(3 * v)))
                                                    .norm());
    }
    for (Eigen::Index k = 0; k < node_count; ++k) {
      worst_momentum = std::max(worst_momentum, (step.momentum()[static_cast<std::size_t>(k)] -
                                                 Vec3(momentum_expected.segment<3>(3 * k)))
                                                    .norm());
    }
    const double residual_bound = tolerance * first_residual;
    EXPECT_LT(worst_velocity, residual_bound / R.minCoeff()) << "tolerance " << tolerance;
    EXPECT_LT(worst_momentum, residual_bound * (1.0 + R.maxCoeff() / R.minCoeff()))
        << "tolerance " << tolerance;
    if (previous_iterations > 0) {
      EXPECT_LT(iterations, previous_iterations);
    }
    previous_iterations = iterations;
  }
  EXPECT_GT(momentum_expected.cwiseAbs().maxCoeff(), 1e-4);  // the friction did act
}

}  // namespace
}  // namespace rbcsim::coupling
