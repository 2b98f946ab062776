#include "coupling/membrane_friction.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace rbcsim::coupling {

namespace {

// `order` := the indices of `keys` sorted by key, equal keys in index order (a least-significant-
// digit radix sort, 11 bits a pass, as many passes as the largest key needs).
void stable_sort_by_key(std::span<const std::size_t> keys, std::vector<std::uint32_t>& order,
                        std::vector<std::uint32_t>& scratch) {
  constexpr unsigned kDigitBits = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
  order.resize(keys.size());
  scratch.resize(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
  const std::size_t largest = keys.empty() ? 0 : *std::max_element(keys.begin(), keys.end());
  std::array<std::uint32_t, kBuckets + 1> start{};
  for (unsigned shift = 0; shift < 64 && (largest >> shift) != 0; shift += kDigitBits) {
    start.fill(0);
    for (const std::size_t key : keys) ++start[((key >> shift) & (kBuckets - 1)) + 1];
    for (std::size_t b = 0; b < kBuckets; ++b) start[b + 1] += start[b];
    for (const std::uint32_t i : order) scratch[start[(keys[i] >> shift) & (kBuckets - 1)]++] = i;
    order.swap(scratch);
  }
}

}  // namespace
namespace {

double dot(std::span<const Vec3> a, std::span<const Vec3> b) {
  double sum = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) sum += a[k].dot(b[k]);
  return sum;
}

}  // namespace

void ImplicitMembraneFriction::prepare(const ibm::InterpolationStencil& stencil) {
  correction_kept_ = false;
  slot_weight_.clear();
  slot_offsets_.assign(1, 0);
  slot_lattice_node_.clear();
  slot_vertex_.clear();
  for (std::size_t v = 0; v < stencil.point_count(); ++v) {
    const auto nodes = stencil.nodes(v);
    slot_lattice_node_.insert(slot_lattice_node_.end(), nodes.begin(), nodes.end());
    slot_vertex_.insert(slot_vertex_.end(), nodes.size(), static_cast<std::uint32_t>(v));
    const auto weights = stencil.weights(v);
    slot_weight_.insert(slot_weight_.end(), weights.begin(), weights.end());
    slot_offsets_.push_back(static_cast<std::uint32_t>(slot_lattice_node_.size()));
  }
  // The slots in the order of their lattice node, and within a node in slot order (vertices
  // ascending, so that spreading is a gather per node that sums in the order a scatter over the
  // vertices would): a stable radix sort. Sorting the nodes and finding each slot's among them by
  // bisection took about 8 % of a suspension's step at 2562 vertices.
  stable_sort_by_key(slot_lattice_node_, slot_order_, sort_scratch_);
  const std::size_t slot_count = slot_lattice_node_.size();
  nodes_.clear();
  slot_node_.resize(slot_count);
  node_slot_offsets_.assign(1, 0);
  node_slot_vertex_.resize(slot_count);
  node_slot_weight_.resize(slot_count);
  for (std::size_t r = 0; r < slot_count; ++r) {
    const std::uint32_t slot = slot_order_[r];
    const std::size_t node = slot_lattice_node_[slot];
    if (nodes_.empty() || nodes_.back() != node) {
      if (!nodes_.empty()) node_slot_offsets_.push_back(static_cast<std::uint32_t>(r));
      nodes_.push_back(node);
    }
    slot_node_[slot] = static_cast<std::uint32_t>(nodes_.size() - 1);
    node_slot_vertex_[r] = slot_vertex_[slot];
    node_slot_weight_[r] = slot_weight_[slot];
  }
  if (!nodes_.empty()) node_slot_offsets_.push_back(static_cast<std::uint32_t>(slot_count));
}

std::size_t ImplicitMembraneFriction::apply(
    const ibm::InterpolationStencil& stencil, std::span<const Vec3> positions_lu,
    const membrane::EdgeNetwork& network, const membrane::EdgeFrictionParameters& friction_lu,
    double dt_steps, lattice::FluidSolver& fluid, const LatestForce& latest_force,
    std::span<Vec3> membrane_velocities_lu, const ImplicitFrictionSettings& settings) {
  const std::size_t iterations = solve(stencil, positions_lu, network, friction_lu, dt_steps, fluid,
                                       latest_force, membrane_velocities_lu, settings);
  add_momentum_to(fluid);
  return iterations;
}

void ImplicitMembraneFriction::add_momentum_to(lattice::FluidSolver& fluid) const {
  fluid.add_momentum(nodes_, momentum_);
}

bool ImplicitMembraneFriction::add_previous_correction(std::span<Vec3> velocity) const {
  bool added = false;
  std::size_t p = 0, q = 0;
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    while (p < previous_nodes_.size() && previous_nodes_[p] < nodes_[k]) ++p;
    if (p == previous_nodes_.size()) break;
    if (previous_nodes_[p] != nodes_[k]) continue;
    velocity[k] += previous_correction_[p];
    added = true;
    // Where the solve before that had the node too, the line through the two: c1 + (c1 - c2).
    while (q < older_nodes_.size() && older_nodes_[q] < nodes_[k]) ++q;
    if (q < older_nodes_.size() && older_nodes_[q] == nodes_[k]) {
      velocity[k] += previous_correction_[p] - older_correction_[q];
    }
  }
  return added;
}

void ImplicitMembraneFriction::keep_correction() {
  // Once per prepare(): a process that solved adopts its own solution again (parallel runs).
  if (!correction_kept_) {
    older_nodes_.swap(previous_nodes_);
    older_correction_.swap(previous_correction_);
    correction_kept_ = true;
  }
  previous_nodes_ = nodes_;
  previous_correction_.resize(nodes_.size());
}

namespace {

// One solve's correction in a checkpoint: its nodes (as doubles, exact below 2^53) and values.
void put_correction(StateArchive& archive, const std::string& name,
                    std::span<const std::size_t> nodes, std::span<const Vec3> correction) {
  archive.put(name + "_nodes", std::vector<double>(nodes.begin(), nodes.end()));
  archive.put(name + "_correction_lu", correction);
}

void take_correction(StateArchive& archive, const std::string& name,
                     std::vector<std::size_t>& nodes, std::vector<Vec3>& correction) {
  const auto stored = archive.take(name + "_nodes", std::nullopt);
  nodes.assign(stored.size(), 0);
  for (std::size_t k = 0; k < stored.size(); ++k) nodes[k] = static_cast<std::size_t>(stored[k]);
  correction.resize(stored.size());
  archive.take(name + "_correction_lu", correction);
}

}  // namespace

void ImplicitMembraneFriction::save_state(StateArchive& archive, const std::string& prefix) const {
  put_correction(archive, prefix + "friction", previous_nodes_, previous_correction_);
  put_correction(archive, prefix + "friction_older", older_nodes_, older_correction_);
}

void ImplicitMembraneFriction::restore_state(StateArchive& archive, const std::string& prefix) {
  take_correction(archive, prefix + "friction", previous_nodes_, previous_correction_);
  take_correction(archive, prefix + "friction_older", older_nodes_, older_correction_);
}

std::size_t ImplicitMembraneFriction::solve(
    const ibm::InterpolationStencil& stencil, std::span<const Vec3> positions_lu,
    const membrane::EdgeNetwork& network, const membrane::EdgeFrictionParameters& friction_lu,
    double dt_steps, const lattice::FluidSolver& fluid, const LatestForce& latest_force,
    std::span<Vec3> membrane_velocities_lu, const ImplicitFrictionSettings& settings) {
  prepare(stencil);
  // The fluid as the next collision will find it (the populations after streaming; its force's
  // half is added from `latest_force` in solve_with_moments): the friction must act on that
  // state, not on the latest collision's velocity, which streaming has since moved by a link
  // (acting on the stale one pumps energy into the flow).
  std::vector<double> density(nodes_.size());
  std::vector<Vec3> momentum_lu(nodes_.size());
  fluid.pre_collision_moments(nodes_, density, momentum_lu);
  return solve_with_moments(positions_lu, network, friction_lu, dt_steps, density, momentum_lu,
                            latest_force, membrane_velocities_lu, settings);
}

void ImplicitMembraneFriction::append_solution(std::vector<double>& values) const {
  for (const Vec3& m : momentum_) values.insert(values.end(), {m.x(), m.y(), m.z()});
  for (const Vec3& c : previous_correction_) values.insert(values.end(), {c.x(), c.y(), c.z()});
}

std::span<const double> ImplicitMembraneFriction::adopt_solution(std::span<const double> values) {
  const std::size_t count = 6 * nodes_.size();
  if (values.size() < count) {
    throw std::invalid_argument(
        "ImplicitMembraneFriction::adopt_solution: " + std::to_string(values.size()) +
        " values for " + std::to_string(count));
  }
  const std::size_t node_count = nodes_.size();
  momentum_.resize(node_count);
  keep_correction();
  for (std::size_t k = 0; k < node_count; ++k) {
    momentum_[k] = Vec3(values[3 * k], values[3 * k + 1], values[3 * k + 2]);
    const std::size_t c = 3 * (node_count + k);
    previous_correction_[k] = Vec3(values[c], values[c + 1], values[c + 2]);
  }
  return values.subspan(count);
}

std::size_t ImplicitMembraneFriction::solve_with_moments(
    std::span<const Vec3> positions_lu, const membrane::EdgeNetwork& network,
    const membrane::EdgeFrictionParameters& friction_lu, double dt_steps,
    std::span<const double> density, std::span<const Vec3> momentum_lu,
    const LatestForce& latest_force, std::span<Vec3> membrane_velocities_lu,
    const ImplicitFrictionSettings& settings) {
  const std::size_t node_count = nodes_.size();
  const std::size_t vertex_count = slot_offsets_.size() - 1;
  if (density.size() != node_count || momentum_lu.size() != node_count ||
      positions_lu.size() != vertex_count ||
      !(latest_force.vertex_forces_lu.empty() ||
        latest_force.vertex_forces_lu.size() == vertex_count)) {
    throw std::invalid_argument("ImplicitMembraneFriction::solve_with_moments: moments of " +
                                std::to_string(density.size()) + " nodes for " +
                                std::to_string(node_count) + ", " +
                                std::to_string(positions_lu.size()) + " positions and " +
                                std::to_string(latest_force.vertex_forces_lu.size()) +
                                " forces for " + std::to_string(vertex_count) + " vertices");
  }
  const auto axes = membrane::edge_axes(positions_lu, network);
  // S x (nodes -> vertices), in slot order.
  auto interpolate = [&](std::span<const Vec3> x, std::span<Vec3> out) {
    for (std::size_t v = 0; v < vertex_count; ++v) {
      Vec3 sum = Vec3::Zero();
      for (std::uint32_t s = slot_offsets_[v]; s < slot_offsets_[v + 1]; ++s) {
        sum += slot_weight_[s] * x[slot_node_[s]];
      }
      out[v] = sum;
    }
  };
  // (S^T y) at node k, summed over its slots in vertex order.
  auto spread_at = [&](std::span<const Vec3> y, std::size_t k) {
    Vec3 sum = Vec3::Zero();
    for (std::uint32_t s = node_slot_offsets_[k]; s < node_slot_offsets_[k + 1]; ++s) {
      sum += node_slot_weight_[s] * y[node_slot_vertex_[s]];
    }
    return sum;
  };
  auto spread = [&](std::span<const Vec3> y, std::span<Vec3> out) {
    for (std::size_t k = 0; k < node_count; ++k) out[k] = spread_at(y, k);
  };
  // u = (m + F/2) / rho, Guo's velocity of the next collision with the latest force (header).
  std::vector<Vec3> fluid_velocity(node_count);
  for (std::size_t k = 0; k < node_count; ++k) {
    Vec3 force = latest_force.body_force_lu;
    if (!latest_force.vertex_forces_lu.empty()) {
      force += spread_at(latest_force.vertex_forces_lu, k);
    }
    fluid_velocity[k] = (momentum_lu[k] + 0.5 * force) / density[k];
  }
  std::vector<Vec3> vertex_values(vertex_count), resistance(vertex_count);
  // A x = rho x + dt S^T Gamma S x.
  auto apply_operator = [&](std::span<const Vec3> x, std::span<Vec3> out) {
    interpolate(x, vertex_values);
    std::fill(resistance.begin(), resistance.end(), Vec3::Zero());
    membrane::add_friction_resistance(axes, vertex_values, network, friction_lu, resistance);
    for (std::size_t k = 0; k < node_count; ++k) {
      out[k] = density[k] * x[k] + dt_steps * spread_at(resistance, k);
    }
  };
  // Preconditioner: per node, rho I + dt sum over the vertices it serves of w^2 times the
  // vertex's diagonal block of Gamma.
  std::vector<Eigen::Matrix3d> vertex_blocks(vertex_count, Eigen::Matrix3d::Zero());
  membrane::add_friction_diagonal(axes, network, friction_lu, vertex_blocks);
  std::vector<Eigen::Matrix3d> inverse_blocks(node_count, Eigen::Matrix3d::Zero());
  for (std::size_t k = 0; k < node_count; ++k) {
    inverse_blocks[k] = density[k] * Eigen::Matrix3d::Identity();
  }
  for (std::size_t v = 0; v < vertex_count; ++v) {
    for (std::uint32_t s = slot_offsets_[v]; s < slot_offsets_[v + 1]; ++s) {
      const double w = slot_weight_[s];
      inverse_blocks[slot_node_[s]] += dt_steps * w * w * vertex_blocks[v];
    }
  }
  for (auto& block : inverse_blocks) block = block.inverse().eval();

  std::vector<Vec3> velocity = fluid_velocity;  // u', first at u
  std::vector<Vec3> product(node_count), residual(node_count), preconditioned(node_count),
      direction(node_count);
  apply_operator(velocity, product);
  double momentum_squared = 0.0;
  for (std::size_t k = 0; k < node_count; ++k) {
    residual[k] = density[k] * fluid_velocity[k] - product[k];
    momentum_squared += (density[k] * fluid_velocity[k]).squaredNorm();
  }
  // Relative to the residual at u' = u (the friction there), but never below round-off of the
  // momentum itself (a rigid motion meets no friction: there that residual is round-off).
  constexpr double kRoundOff = 1e-13;
  const double tolerance_squared =
      std::max(settings.relative_tolerance * settings.relative_tolerance * dot(residual, residual),
               kRoundOff * kRoundOff * momentum_squared);
  if (add_previous_correction(velocity)) {
    apply_operator(velocity, product);
    for (std::size_t k = 0; k < node_count; ++k) {
      residual[k] = density[k] * fluid_velocity[k] - product[k];
    }
  }
  for (std::size_t k = 0; k < node_count; ++k) preconditioned[k] = inverse_blocks[k] * residual[k];
  direction = preconditioned;
  double rho = dot(residual, preconditioned);
  double residual_squared = dot(residual, residual);
  std::size_t iterations = 0;
  for (;; ++iterations) {
    if (residual_squared <= tolerance_squared) break;
    if (iterations == settings.max_iterations) {
      throw RuntimeFailure(
          "membrane viscosity: the implicit friction step did not converge in " +
          std::to_string(settings.max_iterations) + " iterations (residual " +
          format_significant(std::sqrt(residual_squared / std::max(tolerance_squared, 1e-300)) *
                             settings.relative_tolerance) +
          " of the first)");
    }
    apply_operator(direction, product);
    const double step = rho / dot(direction, product);
    // One pass: the update, the preconditioned residual and both of its sums (each in node
    // order, as separate passes would add them).
    double next_rho = 0.0;
    residual_squared = 0.0;
    for (std::size_t k = 0; k < node_count; ++k) {
      velocity[k] += step * direction[k];
      residual[k] -= step * product[k];
      preconditioned[k] = inverse_blocks[k] * residual[k];
      residual_squared += residual[k].dot(residual[k]);
      next_rho += residual[k].dot(preconditioned[k]);
    }
    const double beta = next_rho / rho;
    rho = next_rho;
    for (std::size_t k = 0; k < node_count; ++k) {
      direction[k] = preconditioned[k] + beta * direction[k];
    }
  }
  keep_correction();
  for (std::size_t k = 0; k < node_count; ++k) {
    previous_correction_[k] = velocity[k] - fluid_velocity[k];
  }
  // The momentum exchanged is the friction impulse at the solution, -dt S^T Gamma S u', rather
  // than rho (u' - u): equal to the tolerance, and it sums to zero exactly (each edge's pair
  // cancels, each vertex's weights sum to 1), converged or not.
  interpolate(velocity, membrane_velocities_lu);
  std::fill(resistance.begin(), resistance.end(), Vec3::Zero());
  membrane::add_friction_resistance(axes, membrane_velocities_lu, network, friction_lu, resistance);
  momentum_.resize(node_count);
  spread(resistance, momentum_);
  for (auto& value : momentum_) value *= -dt_steps;
  return iterations;
}

}  // namespace rbcsim::coupling
