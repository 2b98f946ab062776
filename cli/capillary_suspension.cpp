#include "capillary_suspension.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "cases/json_values.hpp"
#include "cases/suspension_output.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/wall_clock.hpp"
#include "coupling/snapshot.hpp"
#include "io/csv_table.hpp"
#include "mesh/geometry.hpp"
#include "run_directory.hpp"
#include "setup/coupling_from_config.hpp"
#include "setup/suspension_from_config.hpp"

namespace rbcsim::cli {
namespace {

constexpr std::size_t kProgressIntervalSteps = 500;

void write_tables(const std::filesystem::path& directory, const cases::SuspensionRun& run,
                  const cases::SuspensionSettings& settings) {
  std::vector<std::vector<double>> rows;
  for (const auto& sample : run.samples) rows.push_back(cases::suspension_table_row(sample));
  io::write_csv_file(directory / "suspension_timeseries.csv", cases::suspension_table_columns(),
                     rows);
  rows.clear();
  for (const auto& sample : run.cell_samples) {
    rows.push_back(cases::suspension_cell_table_row(sample, run.cell_morphologies));
  }
  io::write_csv_file(directory / "cells_timeseries.csv", cases::suspension_cell_table_columns(),
                     rows);
  rows.clear();
  for (const auto& sample : run.samples) {
    for (auto& row : cases::hematocrit_profile_rows(sample, settings))
      rows.push_back(std::move(row));
  }
  io::write_csv_file(directory / "hematocrit_profile.csv", cases::hematocrit_profile_columns(),
                     rows);
}

void print_summary(const nlohmann::ordered_json& result, const cases::SuspensionRun& run,
                   const RunDirectory& directory) {
  const auto& s = result["suspension"];
  std::printf("capillary (tube suspension), %s\n", result["morphology"].get<std::string>().c_str());
  std::printf(
      "tube %.4g um x %.4g um (periodic), %zu cells %s, hematocrit %.4f (packed in %zu "
      "iterations)\n",
      s["tube_diameter_um"].get<double>(), s["tube_length_um"].get<double>(),
      run.cell_morphologies.size(), s["cells_per_morphology"].dump().c_str(), run.packed_hematocrit,
      run.packing_iterations);
  std::printf(
      "drive: plasma mean velocity %.4g m/s (pseudo-shear rate %.4g 1/s), gradient %.4g "
      "Pa/m\n",
      s["plasma_mean_velocity_m_per_s"].get<double>(), run.pseudo_shear_rate_per_s,
      run.pressure_gradient_Pa_per_m);
  const auto& a = run.averages;
  std::printf(
      "over the last %zu samples: relative apparent viscosity %.4f +- %.3g, discharge "
      "hematocrit %.4f (H_T/H_D %.4f), cell-free layer %.3f um\n",
      a.samples, a.relative_apparent_viscosity, a.relative_apparent_viscosity_sd,
      a.discharge_hematocrit, s["tube_to_discharge_hematocrit"].get<double>(),
      a.cell_free_layer_um);
  std::printf(
      "the flow carried the cells %.3g um on average, %.3g tube diameters (a packing develops "
      "into blood over 25-50)\n",
      s["cell_travel_um"].get<double>(), s["cell_travel_tube_diameters"].get<double>());
  std::printf(
      "%zu steps (%.4g s), steps with a near overlap %zu, with a capped contact push "
      "%zu: %s\n",
      run.steps, run.time_s, run.close_contact_steps, run.capped_contact_steps,
      run.stop_reason.c_str());
  std::printf("wall time %.1f s, %d thread(s); run directory %s\n", directory.elapsed_s(),
              directory.threads(), directory.path().c_str());
}

}  // namespace

bool wants_suspension(const config::Config& config) {
  const bool tube = config.string("capillary.geometry") == "tube";
  const bool hematocrit = config.number("suspension.hematocrit") > 0.0;
  const bool placed = !config.cell_list("suspension.cells").empty();
  if (hematocrit && placed) {
    throw InputError("suspension.cells",
                     "cells placed by hand and --hematocrit exclude each other: give one");
  }
  if (tube && !hematocrit && !placed) {
    throw InputError("suspension.hematocrit",
                     "the tube holds a suspension: give --hematocrit (> 0) or suspension.cells");
  }
  if ((hematocrit || placed) && !tube) {
    throw InputError(hematocrit ? "suspension.hematocrit" : "suspension.cells",
                     "suspensions run in the straight periodic tube only: add --geometry tube");
  }
  if (tube && !config.string("capillary.wall_file").empty()) {
    throw InputError("capillary.wall_file",
                     "a suspension runs in the built-in tube, not a wall file");
  }
  return tube;
}

void run_suspension_command(const config::ConfigRequest& request, const config::Config& config,
                            const CommonOptions& common, const CheckpointOptions& checkpoint) {
  if (config.integer("capillary.orientations") != 1) {
    throw InputError("capillary.orientations",
                     "release orientations are for one cell; a suspension's cells are turned at "
                     "random (suspension.seed)");
  }
  const auto mix = setup::suspension_mix_from(config);
  const auto compression = setup::suspension_compression_from(config);
  const auto simulated = setup::compressed_suspension_config(config, compression.factor);
  const auto settings = setup::suspension_settings_from(simulated);
  std::vector<std::string> import_notices;
  const auto morphologies =
      setup::suspension_morphologies_from(request, mix, compression.factor, &import_notices);
  print_notices(import_notices);
  // Printed once the input has passed every check, so that bad input stays one line.
  const auto contact_notice = setup::contact_range_notice(config);
  const double radius_um = 0.5 * settings.tube_diameter_um;
  const auto cells = settings.placed_cells.empty()
                         ? setup::packed_cell_kinds(
                               morphologies, mix,
                               std::numbers::pi * radius_um * radius_um * settings.tube_length_um,
                               config.number("suspension.hematocrit"))
                         : setup::placed_cell_kinds(mix, config.cell_list("suspension.cells"));
  std::vector<std::int32_t> kinds(cells.begin(), cells.end());

  const RunDirectory directory("capillary", common, config);
  std::string names;
  for (const auto& name : mix.names) names += (names.empty() ? "" : ", ") + name;
  const setup::CellMesh described{
      morphologies.front().mesh,
      "suspension of " + std::to_string(cells.size()) + " cells (" + names + ")",
      {},
      {}};
  const cases::SuspensionPhysics physics{
      setup::fluid_parameters_from(simulated),
      setup::coupling_parameters_from(simulated, directory.path()),
      config::make_unit_converter(simulated)};
  const auto intervals = setup::snapshot_intervals_from(simulated, physics.units, directory.path());
  const Progress progress(common);
  const double duration_s = config.number("suspension.duration_s");
  WallTimeLeft time_left(duration_s);
  bool started = false;
  auto run = cases::run_suspension(
      morphologies, cells, physics, settings, [&](coupling::CoupledSimulation& simulation) {
        coupling::add_snapshot_output(simulation, directory.path(), intervals, kinds);
        simulation.add_observer(
            {"progress", kProgressIntervalSteps, [&](const coupling::CoupledSimulation& s) {
               const double time_s = s.time_s() * compression.factor;
               const double wall_s = directory.elapsed_s();
               progress.update("suspension: step " + std::to_string(s.time_step()) +
                               ", t = " + format_significant(time_s) + " of " +
                               format_significant(duration_s) + " s, " +
                               format_number(std::round(wall_s)) + " s" +
                               time_left.text(time_s, wall_s));
             }});
        // After the output observers (a resume restores their state), before the directory is
        // started (a refused checkpoint leaves no file behind).
        wire_checkpoints(simulation, checkpoint, directory, config);
        if (contact_notice) print_notices(std::span(&*contact_notice, 1));
        directory.start(config, described);
        started = true;
      });
  progress.done();
  if (!started) directory.start(config, described);
  setup::to_physical_units(run, compression.factor);
  write_tables(directory.path(), run, settings);

  auto result = run.interrupted ? directory.result_head_with_status("interrupted")
                                : directory.result_head(run.ok());
  if (!run.ok()) result["failure"] = run.failure;
  std::vector<std::string> morphology_names(mix.names.begin(), mix.names.end());
  result["suspension"] = cases::suspension_result_section(morphology_names, settings, run);
  // The settings are the simulated ones: the user's drive and duration are the physical ones.
  result["suspension"]["plasma_mean_velocity_m_per_s"] =
      config.number("suspension.plasma_mean_velocity_m_per_s");
  if (settings.packing.scale < 1.0) {
    result["suspension"]["growth_time_s"] = config.number("suspension.growth_time_s");
  }
  result["suspension"]["time_scale"] = {
      {"compressed", compression.factor != 1.0},
      {"factor", compression.factor},
      {"physical_reynolds_number", compression.physical_reynolds_number},
      {"simulated_reynolds_number", compression.simulated_reynolds_number}};
  result["headline"] = {{"relative_apparent_viscosity", run.averages.relative_apparent_viscosity},
                        {"discharge_hematocrit", run.averages.discharge_hematocrit},
                        {"tube_hematocrit", run.averages.tube_hematocrit},
                        {"cell_free_layer_um", run.averages.cell_free_layer_um}};
  result["files"] = {{"config", "config.json"},
                     {"timeseries", "suspension_timeseries.csv"},
                     {"cells", "cells_timeseries.csv"},
                     {"hematocrit_profile", "hematocrit_profile.csv"},
                     {"membrane", coupling::membrane_series_file(intervals.format, true)},
                     {"fluid", coupling::fluid_series_file(intervals.format)}};
  result["phase_ms_per_step"] = cases::phase_ms_per_step_json(run.phase_times);
  directory.write_json("result.json", result);
  if (common.json) {
    std::cout << result.dump(2) << '\n';
  } else if (!common.quiet) {
    print_summary(result, run, directory);
  }
  if (run.interrupted) throw Interrupted("capillary: " + run.failure);
  if (!run.ok()) throw RuntimeFailure("capillary: " + run.failure);
}

}  // namespace rbcsim::cli
