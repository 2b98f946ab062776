// Edge friction (edge_friction.hpp). Each vertex sums the forces of its edges in the order of the
// topology's vertex-edge lists, computing each edge's force itself: the two ends of an edge
// compute bitwise opposite forces (x_j - x_i and v_j - v_i are exact negations), so the total
// force vanishes to round-off and no scatter is needed (Mirheo loops over vertex rings the same
// way).
#include "membrane/edge_friction.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "membrane/parallel.hpp"

namespace rbcsim::membrane {
namespace {

const double kSqrt3 = std::numbers::sqrt3;

// The force on `vertex` from edge `e` at `velocities`.
Vec3 edge_force(std::span<const Vec3> positions, std::span<const Vec3> velocities,
                const mesh::Edge& edge, std::int32_t vertex, const EdgeFrictionParameters& friction) {
  const std::int32_t other = edge.vertex0 == vertex ? edge.vertex1 : edge.vertex0;
  const Vec3 axis = (positions[vertex] - positions[other]).normalized();
  const Vec3 relative = velocities[vertex] - velocities[other];
  return -friction.tangential_pN_s_per_um * relative -
         friction.central_pN_s_per_um * relative.dot(axis) * axis;
}

Vec3 vertex_force(std::span<const Vec3> positions, std::span<const Vec3> velocities,
                  const EdgeNetwork& network, const EdgeFrictionParameters& friction,
                  std::size_t v) {
  const auto& offsets = network.vertex_edge_offsets;
  Vec3 sum = Vec3::Zero();
  for (auto k = offsets[v]; k < offsets[v + 1]; ++k) {
    sum += edge_force(positions, velocities, network.edges[network.vertex_edges[k]],
                      static_cast<std::int32_t>(v), friction);
  }
  return sum;
}

double dot(std::span<const Vec3> a, std::span<const Vec3> b) {
  double sum = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v) sum += a[v].dot(b[v]);
  return sum;
}

}  // namespace

const Registry<ViscositySplit>& viscosity_splits() {
  static const Registry<ViscositySplit> splits(
      "viscosity split",
      {{"central",
        "all of it along the edges, gamma_T = 0, gamma_C = 4 eta_m / sqrt3 (Mirheo's and "
        "dpdprops' practice: central forces, angular momentum conserved, no friction under a "
        "rigid rotation)",
        [](double eta) { return EdgeFrictionParameters{4.0 * eta / kSqrt3, 0.0}; }},
       {"fedosov",
        "gamma_C = gamma_T / 3 (Fedosov et al. 2010): gamma_T = 12 eta_m / (13 sqrt3); the "
        "tangential part also damps rigid rotations of the membrane and does not conserve "
        "angular momentum",
        [](double eta) {
          const double tangential = 12.0 * eta / (13.0 * kSqrt3);
          return EdgeFrictionParameters{tangential / 3.0, tangential};
        }}});
  return splits;
}

EdgeFrictionParameters edge_friction_for(double viscosity_Pa_s_um, std::string_view split) {
  return viscosity_splits().find(split, "membrane.viscosity_split").split(viscosity_Pa_s_um);
}

void edge_friction_forces(std::span<const Vec3> positions, std::span<const Vec3> velocities,
                          const EdgeNetwork& network, const EdgeFrictionParameters& friction,
                          std::span<Vec3> forces) {
  parallel_for(network.vertex_count(), [&](std::size_t v) {
    forces[v] = vertex_force(positions, velocities, network, friction, v);
  });
}

double edge_friction_power(std::span<const Vec3> positions, std::span<const Vec3> velocities,
                           const EdgeNetwork& network, const EdgeFrictionParameters& friction) {
  double power = 0.0;
  for (const auto& edge : network.edges) {
    const Vec3 axis = (positions[edge.vertex0] - positions[edge.vertex1]).normalized();
    const Vec3 relative = velocities[edge.vertex0] - velocities[edge.vertex1];
    const double along = relative.dot(axis);
    power += friction.tangential_pN_s_per_um * relative.squaredNorm() +
             friction.central_pN_s_per_um * along * along;
  }
  return power;
}

std::size_t solve_implicit_friction(std::span<const Vec3> positions, std::span<const double> masses,
                                    std::span<const Vec3> target_velocities,
                                    const EdgeNetwork& network,
                                    const EdgeFrictionParameters& friction,
                                    std::span<Vec3> velocities,
                                    const ImplicitFrictionSettings& settings) {
  const std::size_t count = network.vertex_count();
  // The edges' unit axes, fixed during the solve.
  std::vector<Vec3> axes(network.edges.size());
  for (std::size_t e = 0; e < axes.size(); ++e) {
    const auto& edge = network.edges[e];
    axes[e] = (positions[edge.vertex0] - positions[edge.vertex1]).normalized();
  }
  // A x = M x + Gamma x = M x - friction(x), edge by edge in edge order. Serial: one solve is many
  // short passes, for which threads would cost more in synchronisation than they save (a cell at
  // a time; many cells are parallel over cells).
  std::vector<Vec3> product(count);
  auto apply = [&](std::span<const Vec3> x, std::span<Vec3> out) {
    for (std::size_t v = 0; v < count; ++v) out[v] = masses[v] * x[v];
    for (std::size_t e = 0; e < axes.size(); ++e) {
      const auto& edge = network.edges[e];
      const Vec3 relative = x[edge.vertex0] - x[edge.vertex1];
      const Vec3 resisted = friction.tangential_pN_s_per_um * relative +
                            friction.central_pN_s_per_um * relative.dot(axes[e]) * axes[e];
      out[edge.vertex0] += resisted;
      out[edge.vertex1] -= resisted;
    }
  };
  // Block-diagonal preconditioner: the inverse of each vertex's 3x3 block of A,
  // m I + sum over its edges of gamma_T I + gamma_C e e^T.
  std::vector<Eigen::Matrix3d> inverse_blocks(count);
  for (std::size_t v = 0; v < count; ++v) {
    inverse_blocks[v] = masses[v] * Eigen::Matrix3d::Identity();
  }
  for (std::size_t e = 0; e < axes.size(); ++e) {
    const Eigen::Matrix3d block =
        friction.tangential_pN_s_per_um * Eigen::Matrix3d::Identity() +
        friction.central_pN_s_per_um * axes[e] * axes[e].transpose();
    inverse_blocks[network.edges[e].vertex0] += block;
    inverse_blocks[network.edges[e].vertex1] += block;
  }
  for (auto& block : inverse_blocks) block = block.inverse().eval();
  std::vector<Vec3> residual(count), preconditioned(count), direction(count);
  apply(velocities, product);
  double target_norm_squared = 0.0;
  for (std::size_t v = 0; v < count; ++v) {
    const Vec3 right_hand_side = masses[v] * target_velocities[v];
    residual[v] = right_hand_side - product[v];
    target_norm_squared += right_hand_side.squaredNorm();
    preconditioned[v] = inverse_blocks[v] * residual[v];
  }
  if (target_norm_squared == 0.0) {  // at rest: the exact solution, whatever the start
    for (auto& velocity : velocities) velocity.setZero();
    return 0;
  }
  const double tolerance_squared =
      settings.relative_tolerance * settings.relative_tolerance * target_norm_squared;
  direction = preconditioned;
  double rho = dot(residual, preconditioned);
  for (std::size_t iteration = 0; iteration <= settings.max_iterations; ++iteration) {
    if (dot(residual, residual) <= tolerance_squared) return iteration;
    if (iteration == settings.max_iterations) break;
    apply(direction, product);
    const double step = rho / dot(direction, product);
    for (std::size_t v = 0; v < count; ++v) {
      velocities[v] += step * direction[v];
      residual[v] -= step * product[v];
      preconditioned[v] = inverse_blocks[v] * residual[v];
    }
    const double next_rho = dot(residual, preconditioned);
    const double beta = next_rho / rho;
    rho = next_rho;
    for (std::size_t v = 0; v < count; ++v) {
      direction[v] = preconditioned[v] + beta * direction[v];
    }
  }
  throw RuntimeFailure("membrane viscosity: the implicit friction step did not converge in " +
                       std::to_string(settings.max_iterations) + " iterations (residual " +
                       format_significant(std::sqrt(dot(residual, residual) /
                                                    std::max(target_norm_squared, 1e-300))) +
                       " of the target's norm)");
}

}  // namespace rbcsim::membrane
