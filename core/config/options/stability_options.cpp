#include "config/options/option_areas.hpp"
#include "coupling/stability.hpp"

namespace rbcsim::config {
namespace {

// The defaults come from the coupled loop's own struct: one source of truth.
const coupling::StabilityLimits kStabilityDefaults{};

}  // namespace

// docs/physics.md, "Failures": an instability stops the run (exit code 1) with a diagnosis dump;
// these set what counts as one.
void add_stability_options(OptionTable& table) {
  table
      .add_number("stability.max_vertex_step_dx", "dx", kStabilityDefaults.max_vertex_step_lu,
                  "Largest vertex displacement in one step, in lattice spacings.")
      .above(0.0);
  table
      .add_number("stability.force_cap_vertex_fraction", "",
                  kStabilityDefaults.force_cap_vertex_fraction,
                  "Fraction of a cell's vertices whose force may hit membrane.vertex_force_cap_pN "
                  "in one step before the step counts as capped.")
      .at_least(0.0)
      .below(1.0);
  table
      .add_integer("stability.force_cap_max_steps", "",
                   static_cast<int>(kStabilityDefaults.force_cap_max_steps),
                   "Consecutive capped steps of one cell that stop the run.")
      .at_least(1);
  table
      .add_integer("stability.fluid_check_interval_steps", "",
                   static_cast<int>(kStabilityDefaults.fluid_check_interval_steps),
                   "Steps between scans of the whole fluid for non-finite velocities (the cells' "
                   "vertices are checked every step).")
      .at_least(1);
}

}  // namespace rbcsim::config
