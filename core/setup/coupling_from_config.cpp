#include "setup/coupling_from_config.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "parallel/communicator.hpp"
#include "parallel/hdf5_file.hpp"

namespace rbcsim::setup {
namespace {

std::size_t interval_steps(double interval_s, const units::UnitConverter& units) {
  if (interval_s == 0.0) return 0;
  const double steps = std::round(units.to_lattice(units::PhysicalUnit::time_s, interval_s));
  return static_cast<std::size_t>(std::max(steps, 1.0));
}

}  // namespace

lattice::FluidParameters fluid_parameters_from(const config::Config& config) {
  lattice::FluidParameters parameters;
  parameters.collision = config.string("lattice.collision");
  parameters.collision_parameters.tau = config.number("lattice.relaxation_time");
  parameters.collision_parameters.magic_parameter = config.number("lattice.trt_magic");
  parameters.wall_rule = config.string("lattice.wall_rule");
  parameters.kernel = config.string("lattice.kernel");
  parameters.precision = lattice::find_precision(config.string("lattice.precision"));
  // A ratio of viscosities, unchanged when a case scales the plasma's viscosity down (shear's
  // viscosity_scaling, capillary's time_scale_compression): both fluids scale alike.
  parameters.inner_viscosity_ratio = config.number("physics.cytoplasm_viscosity_ratio");
  return parameters;
}

coupling::CouplingParameters coupling_parameters_from(const config::Config& config,
                                                      const std::filesystem::path& run_directory) {
  coupling::CouplingParameters parameters;
  parameters.kernel = config.string("ibm.kernel");
  parameters.point_advance = config.string("ibm.point_advance");
  parameters.cytoplasm_update_lu = config.number("ibm.cytoplasm_update_dx");
  parameters.hold_volume = config.boolean("ibm.hold_volume");
  parameters.sub_spacing_drag = config.boolean("ibm.sub_spacing_drag");
  auto& stability = parameters.stability;
  stability.max_vertex_step_lu = config.number("stability.max_vertex_step_dx");
  stability.force_cap_vertex_fraction = config.number("stability.force_cap_vertex_fraction");
  stability.force_cap_max_steps =
      static_cast<std::size_t>(config.integer("stability.force_cap_max_steps"));
  stability.fluid_check_interval_steps =
      static_cast<std::size_t>(config.integer("stability.fluid_check_interval_steps"));
  parameters.run_directory = run_directory;
  // Every process the run was started on (one without mpirun).
  parameters.processes = parallel::Communicator::world();
  parameters.block_planes = static_cast<int>(config.integer("lattice.block_planes"));
  return parameters;
}

coupling::SnapshotFormat snapshot_format_from(const config::Config& config,
                                              const std::filesystem::path& directory) {
  const std::string format = config.string("output.format");
  const auto hdf5_or_refused = [](const std::string& why) {
    if (!parallel::built_with_hdf5()) {
      throw InputError("output.format", why +
                                            ": this rbcsim was built without HDF5 (cmake "
                                            "-DRBCSIM_HDF5=ON with Debian's libhdf5-openmpi-dev, "
                                            "as scripts/setup.sh does); use vtk");
    }
    return coupling::SnapshotFormat::hdf5;
  };
  if (format == "hdf5") return hdf5_or_refused("hdf5");
  if (format == "vtk") return coupling::SnapshotFormat::vtk;
  // auto: a resumed run goes on in the format its series were started in, whatever the process
  // count now.
  const auto has = [&directory](const char* file) {
    return !directory.empty() && std::filesystem::exists(directory / file);
  };
  if (has("cells.xdmf") || has("fluid.xdmf")) {
    return hdf5_or_refused("auto, resuming the HDF5 series in " + directory.string());
  }
  if (has("cells.pvd") || has("cell0.pvd") || has("fluid.pvd"))
    return coupling::SnapshotFormat::vtk;
  const bool hdf5 = parallel::built_with_hdf5() && parallel::Communicator::world().size() > 1;
  return hdf5 ? coupling::SnapshotFormat::hdf5 : coupling::SnapshotFormat::vtk;
}

coupling::SnapshotIntervals snapshot_intervals_from(const config::Config& config,
                                                    const units::UnitConverter& units,
                                                    const std::filesystem::path& directory) {
  return {interval_steps(config.number("output.membrane_interval_s"), units),
          interval_steps(config.number("output.fluid_interval_s"), units),
          snapshot_format_from(config, directory)};
}

}  // namespace rbcsim::setup
