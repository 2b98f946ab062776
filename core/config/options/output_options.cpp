#include "config/options/option_areas.hpp"

namespace rbcsim::config {

void add_output_options(OptionTable& table) {
  // Intervals in physical time, so that they do not change when dx or tau (hence dt) do. A
  // membrane snapshot is small (a few hundred kB at 2562 vertices); a fluid snapshot is 7 doubles
  // per node, hence the sparser default.
  table
      .add_number("output.membrane_interval_s", "s", 5e-4,
                  "Time between membrane snapshots (.vtp, every force term); 0: none.")
      .at_least(0.0);
  table
      .add_number("output.fluid_interval_s", "s", 5e-3,
                  "Time between fluid snapshots (.vti: velocity, density, solid mask); 0: none.")
      .at_least(0.0);
}

}  // namespace rbcsim::config
