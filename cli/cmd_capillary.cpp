// rbcsim capillary: one cell through a stenosed capillary (paper §3.3-3.4):
// deformation index against time, transit time through the narrow section, Reynolds and
// capillary numbers.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cases/capillary_output.hpp"
#include "command_registry.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common_options.hpp"
#include "coupling/snapshot.hpp"
#include "io/csv_table.hpp"
#include "run_directory.hpp"
#include "setup/capillary_from_config.hpp"
#include "setup/coupling_from_config.hpp"

namespace rbcsim::cli::capillary_command {
namespace {

// Progress lines every this many steps (when stderr is a terminal).
constexpr std::size_t kProgressIntervalSteps = 1000;

struct CapillaryOptions {
  CommonOptions common;
  CheckpointOptions checkpoint;
  std::optional<std::string> mesh_file;
  std::optional<std::string> geometry;
  std::optional<std::string> wall_file;
};

// The command's own options are --set assignments in disguise, so config.json records them.
config::Config resolve_capillary_config(const CapillaryOptions& options) {
  auto common = options.common;
  auto& request = common.config;
  if (options.mesh_file) assign_option(request, "mesh", "mesh.file", *options.mesh_file);
  if (options.geometry) {
    assign_option(request, "--geometry", "capillary.geometry", *options.geometry);
  }
  if (options.wall_file) {
    assign_option(request, "--wall", "capillary.wall_file", *options.wall_file);
  }
  return resolve_config(common);
}

nlohmann::ordered_json headline(const cases::CapillaryRun& run) {
  nlohmann::ordered_json numbers = {
      {"reynolds_number", run.numbers.reynolds_number},
      {"capillary_number", run.numbers.capillary_number},
      {"peak_deformation_index", run.peak_deformation_index},
      {"final_deformation_index", run.final_deformation_index},
  };
  if (run.transit_time_s) numbers["transit_time_s"] = *run.transit_time_s;
  return numbers;
}

void print_summary(const nlohmann::ordered_json& result, const cases::CapillaryRun& run,
                   const RunDirectory& directory) {
  const auto& section = result["capillary"];
  std::printf("%s\n",
              summary_heading("capillary", section["geometry"].get<std::string>(), result).c_str());
  std::printf("inlet %.4g m/s over %.4g um, Re %.4g, Ca %.4g (G_s %.4g uN/m)\n",
              run.numbers.mean_inlet_velocity_m_per_s, run.numbers.inlet_diameter_um,
              run.numbers.reynolds_number, run.numbers.capillary_number,
              run.numbers.shear_modulus_N_per_m * 1e6);
  std::printf("narrow section %.4g-%.4g um; ", run.narrow_start_um, run.narrow_end_um);
  if (run.transit_time_s) {
    std::printf("transit time %.6g s (entry %.6g s, exit %.6g s)\n", *run.transit_time_s,
                *run.entry_time_s, *run.exit_time_s);
  } else {
    std::printf("NOT PASSED\n");
  }
  std::printf("DI: initial %.4f, peak %.4f at x = %.3g um (t = %.4g s), final %.4f\n",
              run.initial_deformation_index, run.peak_deformation_index, run.peak_centroid_x_um,
              run.peak_time_s, run.final_deformation_index);
  if (!section["max_triangle_area_deviation"].is_null()) {
    std::printf(
        "membrane area (sampled): whole %+.2f to %+.2f %%, largest triangle |dA/A0| %.3f "
        "(membrane.tau_area is its limit)\n",
        100.0 * section["min_area_change"].get<double>(),
        100.0 * section["max_area_change"].get<double>(),
        section["max_triangle_area_deviation"].get<double>());
  }
  std::printf("%zu steps (%.4g s simulated, fluid settled in %zu steps): %s\n", run.steps,
              run.time_s, run.fluid_settling_steps, run.stop_reason.c_str());
  std::printf("wall time %.1f s, %d thread(s); run directory %s\n", directory.elapsed_s(),
              directory.threads(), directory.path().c_str());
}

void write_table(const RunDirectory& directory, const cases::CapillaryRun& run) {
  std::vector<std::vector<double>> rows;
  for (const auto& sample : run.samples) rows.push_back(cases::capillary_table_row(sample));
  io::write_csv_file(directory.path() / "capillary_timeseries.csv",
                     cases::capillary_table_columns(), rows);
}

void add_progress(coupling::CoupledSimulation& simulation, const Progress& progress,
                  const RunDirectory& directory) {
  simulation.add_observer(
      {"progress", kProgressIntervalSteps,
       [&progress, &directory](const coupling::CoupledSimulation& s) {
         const double centroid_x_um = s.frame().to_um(s.cell(0).centroid_lu()).x();
         progress.update("capillary: step " + std::to_string(s.time_step()) +
                         ", t = " + format_number(s.time_s()) + " s, centroid x = " +
                         format_number(std::round(centroid_x_um * 100.0) / 100.0) + " um, " +
                         format_number(std::round(directory.elapsed_s())) + " s");
       }});
}

void run_capillary_command(const CapillaryOptions& options) {
  const auto config = resolve_capillary_config(options);
  const auto wall = setup::capillary_wall_from(config);
  const auto settings = setup::capillary_settings_from(config, wall);
  auto cell_mesh = setup::cell_mesh_from(config);
  setup::add_resolution_notice(cell_mesh, config);
  setup::add_edge_spacing_notice(cell_mesh, config.number("lattice.spacing_um"));
  for (const auto& notice : cell_mesh.notices) std::cerr << "rbcsim: notice: " << notice << '\n';

  const RunDirectory directory("capillary", options.common, config);
  const auto physics = setup::capillary_physics_from(config, wall, directory.path());
  const auto intervals = setup::snapshot_intervals_from(config, physics.units);
  const Progress progress(options.common);
  // The directory is created once every input has been checked (the cell placed in the wall), so
  // bad input leaves no file behind.
  bool started = false;
  const auto run = cases::run_capillary(
      cell_mesh.mesh, physics, settings, [&](coupling::CoupledSimulation& simulation) {
        coupling::add_vtk_output(simulation, directory.path(), intervals);
        add_progress(simulation, progress, directory);
        // Before the directory is started: a refused checkpoint leaves no file behind.
        wire_checkpoints(simulation, options.checkpoint, directory, config);
        directory.start(config, cell_mesh);
        started = true;
      });
  progress.done();
  if (!started) directory.start(config, cell_mesh);

  write_table(directory, run);
  auto result = run.interrupted ? directory.result_head_with_status("interrupted")
                                : directory.result_head(run.ok());
  if (!run.ok()) result["failure"] = run.failure;
  result["headline"] = headline(run);
  result["files"] = {{"config", "config.json"},
                     {"timeseries", "capillary_timeseries.csv"},
                     {"membrane", "cell0.pvd"},
                     {"fluid", "fluid.pvd"}};
  result["capillary"] = cases::capillary_result_section(
      {wall.geometry, settings.cell_axis, physics.membrane.forces}, run);
  directory.write_json("result.json", result);

  if (options.common.json) {
    std::cout << result.dump(2) << '\n';
  } else if (!options.common.quiet) {
    print_summary(result, run, directory);
  }
  if (run.interrupted) throw Interrupted("capillary: " + run.failure);
  if (!run.ok()) throw RuntimeFailure("capillary: " + run.failure);
}

void attach_capillary(CLI::App& application) {
  auto options = std::make_shared<CapillaryOptions>();
  auto* command = application.add_subcommand(
      "capillary",
      "One cell through a stenosed capillary: deformation index vs time, transit time through "
      "the narrow section, Reynolds and capillary numbers");
  command
      ->add_option("mesh", options->mesh_file,
                   "Cell mesh file (STL, OBJ, PLY, OFF; its z axis is taken as the symmetry "
                   "axis); default: the morphology's built-in shape")
      ->type_name("MESH");
  command
      ->add_option("--geometry", options->geometry,
                   "Built-in capillary: paper-validation (default; 31.2 um, 10.2 um, throat "
                   "6.75 um) or paper-morphology (42 um, 10 um, throat 6.8 um)")
      ->type_name("NAME");
  command
      ->add_option("--wall", options->wall_file,
                   "Wall surface (STL, fluid inside, lumen open along x) instead of the built-in "
                   "capillary; then give capillary.inlet_velocity_m_per_s and set "
                   "capillary.wall_repulsion_pN_per_um2=0")
      ->type_name("FILE.stl");
  add_common_options(command, options->common);
  add_checkpoint_options(command, options->checkpoint, options->common);
  command->callback([options] { run_capillary_command(*options); });
}

const bool registered = register_command({"capillary", 50, attach_capillary});

}  // namespace
}  // namespace rbcsim::cli::capillary_command
