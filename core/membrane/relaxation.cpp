#include "membrane/relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "common/interrupt.hpp"
#include "minimise/stiffness.hpp"

namespace rbcsim::membrane {
namespace {

// Finite-difference displacement of the power iteration, relative to the mean edge length:
// small enough to stay linear, large enough for round-off (forces ~1 pN, stiffness ~10-100 pN/um).
constexpr double kProbeFraction = 1e-6;

double max_norm(std::span<const Vec3> vectors) {
  double largest = 0.0;
  for (const auto& v : vectors) largest = std::max(largest, v.norm());
  return largest;
}

}  // namespace

double estimate_stiffest_mode_pN_per_um(const MembraneModel& model,
                                        std::span<const Vec3> positions_um) {
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  return minimise::estimate_stiffest_mode(
      [&](std::span<const Vec3> positions, std::span<Vec3> total_pN) {
        model.compute(positions, workspace, forces, ForceDetail::totals);
        std::copy(forces.total_pN.begin(), forces.total_pN.end(), total_pN.begin());
      },
      positions_um, kProbeFraction * mean_reference_edge_um(model.reference()));
}

void share_force_within_rigid_groups(std::span<const std::vector<std::int32_t>> groups,
                                     std::span<Vec3> net_forces_pN) {
  for (const auto& group : groups) {
    Vec3 sum_pN = Vec3::Zero();
    for (const auto vertex : group) sum_pN += net_forces_pN[static_cast<std::size_t>(vertex)];
    const Vec3 mean_pN = sum_pN / static_cast<double>(group.size());
    for (const auto vertex : group) net_forces_pN[static_cast<std::size_t>(vertex)] = mean_pN;
  }
}

RelaxationResult relax_membrane(const MembraneModel& model, std::span<Vec3> positions_um,
                                std::span<const Vec3> external_forces_pN,
                                const RelaxationSettings& settings) {
  const auto count = model.vertex_count();
  if (positions_um.size() != count ||
      (!external_forces_pN.empty() && external_forces_pN.size() != count)) {
    throw std::invalid_argument(
        "relax_membrane: positions and external forces must have one "
        "entry per vertex");
  }
  if (!(settings.mobility_um_per_s_per_pN > 0.0) || !(settings.step_fraction > 0.0) ||
      !(settings.step_fraction < 2.0) || settings.stiffness_update_interval == 0) {
    throw std::invalid_argument(
        "relax_membrane: needs mobility > 0, 0 < step_fraction < 2 and "
        "stiffness_update_interval > 0");
  }
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  RelaxationResult result;
  for (result.iterations = 0;; ++result.iterations) {
    throw_if_interrupted();
    if (result.iterations % settings.stiffness_update_interval == 0) {
      result.stiffest_mode_pN_per_um = estimate_stiffest_mode_pN_per_um(model, positions_um);
      result.time_step_s = settings.step_fraction /
                           (settings.mobility_um_per_s_per_pN * result.stiffest_mode_pN_per_um);
    }
    model.compute(positions_um, workspace, forces, ForceDetail::totals);
    result.capped_vertex_count += forces.capped_vertex_count;
    if (!external_forces_pN.empty()) {
      for (std::size_t i = 0; i < count; ++i) forces.total_pN[i] += external_forces_pN[i];
    }
    share_force_within_rigid_groups(settings.rigid_groups, forces.total_pN);
    result.max_force_pN = max_norm(forces.total_pN);
    result.converged = result.max_force_pN < settings.force_tolerance_pN;
    if (result.converged || result.iterations == settings.max_iterations) return result;

    const double displacement_per_pN_um = settings.mobility_um_per_s_per_pN * result.time_step_s;
    for (std::size_t i = 0; i < count; ++i) {
      positions_um[i] += displacement_per_pN_um * forces.total_pN[i];
    }
    result.simulated_time_s += result.time_step_s;
  }
}

}  // namespace rbcsim::membrane
