#include "config/options/option_areas.hpp"

namespace rbcsim::config {

// DESIGN.md §6: an instability stops the run (exit code 1) with a diagnosis dump; these set what
// counts as one.
void add_stability_options(OptionTable& table) {
  // Half a spacing per step: beyond it the IBM stencils of consecutive steps barely overlap and
  // forward Euler has stopped following the flow.
  table
      .add_number("stability.max_vertex_step_dx", "dx", 0.5,
                  "Largest vertex displacement in one step, in lattice spacings.")
      .above(0.0);
  table
      .add_number("stability.force_cap_vertex_fraction", "", 0.01,
                  "Fraction of a cell's vertices whose force may hit membrane.vertex_force_cap_pN "
                  "in one step before the step counts as capped.")
      .at_least(0.0)
      .below(1.0);
  table
      .add_integer("stability.force_cap_max_steps", "", 100,
                   "Consecutive capped steps of one cell that stop the run.")
      .at_least(1);
  table
      .add_integer("stability.fluid_check_interval_steps", "", 100,
                   "Steps between scans of the whole fluid for non-finite velocities (the cells' "
                   "vertices are checked every step).")
      .at_least(1);
}

}  // namespace rbcsim::config
