// The instability checks of the coupled step (docs/physics.md, "Failures"). Each is cheap (one pass
// over a cell's vertices) so the driver runs them every step; each returns a one-line description
// of the first problem found, for the "step N, cell K: ..." failure message, or nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "common/state_archive.hpp"
#include "common/vec3.hpp"
#include "ibm/grid_view.hpp"

namespace rbcsim::coupling {

struct StabilityLimits {
  // Largest displacement of a vertex in one step: half a spacing (docs/physics.md). Beyond it the
  // stencils of consecutive steps barely overlap and the vertex no longer follows the flow.
  double max_vertex_step_lu = 0.5;
  // A step is "capped" for a cell when more than this fraction of its vertices hit the membrane's
  // force cap; more than force_cap_max_steps capped steps in a row stop the run.
  double force_cap_vertex_fraction = 0.01;
  std::size_t force_cap_max_steps = 100;
  // The whole fluid is scanned for non-finite velocities this often (the vertices every step).
  std::size_t fluid_check_interval_steps = 100;
};

// A non-finite interpolated velocity or new position, or a vertex that moved more than
// max_step_lu between `previous_lu` and `positions_lu`.
std::optional<std::string> find_vertex_motion_problem(std::span<const Vec3> previous_lu,
                                                      std::span<const Vec3> positions_lu,
                                                      std::span<const Vec3> velocities_lu,
                                                      double max_step_lu);

// A vertex outside the grid along a non-periodic axis, or whose nearest node is not fluid (it
// went through a wall or into an inlet or outlet). `solid_mask` may be null (no walls).
std::optional<std::string> find_domain_exit(std::span<const Vec3> positions_lu,
                                            const ibm::GridView& grid,
                                            const std::uint8_t* solid_mask);

// Counts the consecutive steps in which one cell's force cap clamped too many vertices.
class ForceCapMonitor {
 public:
  // Records one step; returns the problem once the limit is exceeded.
  std::optional<std::string> record(std::size_t capped_vertices, std::size_t vertex_count,
                                    double cap_pN, const StabilityLimits& limits);
  // Steps so far in which the cap clamped at least one vertex (reported after a run: the cap is
  // a safety net, never silent physics).
  std::size_t steps_with_capping() const { return steps_with_capping_; }

  // Checkpoints: both counts as `<prefix>force_cap_steps`.
  void save_state(StateArchive& archive, const std::string& prefix) const;
  void restore_state(StateArchive& archive, const std::string& prefix);

 private:
  std::size_t consecutive_capped_steps_ = 0;
  std::size_t steps_with_capping_ = 0;
};

}  // namespace rbcsim::coupling
