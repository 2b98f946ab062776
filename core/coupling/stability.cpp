#include "coupling/stability.hpp"

#include <algorithm>
#include <cmath>

#include "common/format.hpp"

namespace rbcsim::coupling {
namespace {

constexpr std::array<char, 3> kAxisNames = {'x', 'y', 'z'};

std::string vertex_label(std::size_t vertex) { return "vertex " + std::to_string(vertex); }

// std::lround's result (halves away from zero) without its library call, which the portable
// build cannot inline: coordinate - trunc(coordinate) is exact in floating point. The caller has
// checked that the coordinate is finite and, on a bounded axis, inside the grid; a periodic one
// stays far below 2^31 spacings.
int round_half_away_from_zero(double coordinate) {
  auto whole = static_cast<int>(coordinate);
  const double fraction = coordinate - static_cast<double>(whole);
  if (fraction >= 0.5) ++whole;
  if (fraction <= -0.5) --whole;
  return whole;
}

// The node nearest to `position` along one axis, wrapped on a periodic axis; -1 outside.
int nearest_node(double coordinate, int extent, bool periodic) {
  return ibm::wrap_or_drop(round_half_away_from_zero(coordinate), extent, periodic);
}

// True when no vertex can fail find_vertex_motion_problem: one pass without branches or square
// roots (the checks run every step: docs/performance.md). The sum turns NaN when any position or
// velocity is not finite (0 x inf is NaN); the bound sits just below the limit, so a step at the
// limit's last digit goes to the exact test.
bool vertex_motion_clearly_fine(std::span<const Vec3> previous_lu,
                                std::span<const Vec3> positions_lu,
                                std::span<const Vec3> velocities_lu, double max_step_lu) {
  double poison = 0.0;
  double largest_step_squared = 0.0;
  for (std::size_t v = 0; v < positions_lu.size(); ++v) {
    poison += 0.0 * (positions_lu[v].sum() + velocities_lu[v].sum());
    largest_step_squared =
        std::max(largest_step_squared, (positions_lu[v] - previous_lu[v]).squaredNorm());
  }
  return std::isfinite(poison) && largest_step_squared < (1.0 - 1e-12) * max_step_lu * max_step_lu;
}

}  // namespace

std::optional<std::string> find_vertex_motion_problem(std::span<const Vec3> previous_lu,
                                                      std::span<const Vec3> positions_lu,
                                                      std::span<const Vec3> velocities_lu,
                                                      double max_step_lu) {
  if (vertex_motion_clearly_fine(previous_lu, positions_lu, velocities_lu, max_step_lu)) {
    return std::nullopt;
  }
  for (std::size_t v = 0; v < positions_lu.size(); ++v) {
    if (!velocities_lu[v].allFinite()) {
      return vertex_label(v) + ": non-finite fluid velocity interpolated (the flow is unstable)";
    }
    if (!positions_lu[v].allFinite()) return vertex_label(v) + ": non-finite position";
    const double step_lu = (positions_lu[v] - previous_lu[v]).norm();
    if (step_lu > max_step_lu) {
      return vertex_label(v) + " moved " + format_number(step_lu) + " dx in one step (limit " +
             format_number(max_step_lu) +
             " dx, stability.max_vertex_step_dx): forces too large for the time step";
    }
  }
  return std::nullopt;
}

std::optional<std::string> find_domain_exit(std::span<const Vec3> positions_lu,
                                            const ibm::GridView& grid,
                                            const std::uint8_t* solid_mask) {
  const std::array<int, 3> extents = {grid.nx, grid.ny, grid.nz};
  const std::array<bool, 3> periodic_axes = {grid.periodic_x, grid.periodic_y, grid.periodic_z};
  for (std::size_t v = 0; v < positions_lu.size(); ++v) {
    std::array<int, 3> node{};
    for (int axis = 0; axis < 3; ++axis) {
      const int extent = extents[axis];
      const bool periodic = periodic_axes[axis];
      const double coordinate = positions_lu[v][axis];
      if (!std::isfinite(coordinate)) return vertex_label(v) + ": non-finite position";
      if (!periodic && !(coordinate >= 0.0 && coordinate <= extent - 1.0)) {
        return vertex_label(v) + " left the domain along " + kAxisNames[axis] + " (at " +
               format_number(coordinate) + " dx; nodes 0 to " + std::to_string(extent - 1) + ")";
      }
      node[axis] = nearest_node(coordinate, extent, periodic);
    }
    if (solid_mask != nullptr &&
        solid_mask[ibm::node_index(grid, node[0], node[1], node[2])] != 0) {
      return vertex_label(v) + " entered the non-fluid node (" + std::to_string(node[0]) + ", " +
             std::to_string(node[1]) + ", " + std::to_string(node[2]) +
             "): it crossed a wall, inlet or outlet";
    }
  }
  return std::nullopt;
}

std::optional<std::string> ForceCapMonitor::record(std::size_t capped_vertices,
                                                   std::size_t vertex_count, double cap_pN,
                                                   const StabilityLimits& limits) {
  if (capped_vertices > 0) ++steps_with_capping_;
  const bool capped_step = static_cast<double>(capped_vertices) >
                           limits.force_cap_vertex_fraction * static_cast<double>(vertex_count);
  consecutive_capped_steps_ = capped_step ? consecutive_capped_steps_ + 1 : 0;
  if (consecutive_capped_steps_ <= limits.force_cap_max_steps) return std::nullopt;
  return "the vertex force cap (" + format_number(cap_pN) + " pN) clamped more than " +
         format_number(100.0 * limits.force_cap_vertex_fraction) + " % of the vertices for " +
         std::to_string(consecutive_capped_steps_) +
         " consecutive steps (stability.force_cap_max_steps): the membrane is overstretched";
}

void ForceCapMonitor::save_state(StateArchive& archive, const std::string& prefix) const {
  archive.put(prefix + "force_cap_steps", {static_cast<double>(consecutive_capped_steps_),
                                           static_cast<double>(steps_with_capping_)});
}

void ForceCapMonitor::restore_state(StateArchive& archive, const std::string& prefix) {
  const auto steps = archive.take(prefix + "force_cap_steps", 2);
  consecutive_capped_steps_ = static_cast<std::size_t>(steps[0]);
  steps_with_capping_ = static_cast<std::size_t>(steps[1]);
}

}  // namespace rbcsim::coupling
