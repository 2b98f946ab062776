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
  table.add_choice(
      "output.format", {"auto", "vtk", "hdf5"}, "auto",
      "Snapshot files: vtk (.vtp, .vti, .pvd; across processes gathered and written by "
      "rank 0); hdf5 (h5/*.h5 with cells.xdmf and fluid.xdmf for ParaView, every "
      "process writing its part; needs a build with RBCSIM_HDF5); auto: vtk on one "
      "process, hdf5 across processes when built with it, and on --resume the format of "
      "the series already in the run directory.");
}

}  // namespace rbcsim::config
