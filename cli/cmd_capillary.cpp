// rbcsim capillary: one cell through a stenosed capillary (paper §3.3-3.4): deformation index
// against time, transit time through the narrow section, Reynolds and capillary numbers. With
// --geometry tube --hematocrit H: many cells in a straight tube (capillary_suspension.hpp).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "capillary_suspension.hpp"
#include "cases/capillary_output.hpp"
#include "cases/json_values.hpp"
#include "cases/release_orientations.hpp"
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
  std::optional<std::string> orientations;
  // The suspension (capillary_suspension.hpp).
  std::optional<std::string> hematocrit;
  std::optional<std::string> mix;
  std::optional<std::string> diameter_um;
  std::optional<std::string> length_um;
};

// The command's own options are --set assignments in disguise, so config.json records them.
config::ConfigRequest capillary_request(const CapillaryOptions& options) {
  auto request = options.common.config;
  if (options.mesh_file) assign_option(request, "mesh", "mesh.file", *options.mesh_file);
  if (options.geometry) {
    assign_option(request, "--geometry", "capillary.geometry", *options.geometry);
  }
  if (options.wall_file) {
    assign_option(request, "--wall", "capillary.wall_file", *options.wall_file);
  }
  if (options.orientations) {
    assign_option(request, "--orientations", "capillary.orientations", *options.orientations);
  }
  for (const auto& [value, option, path] :
       {std::tuple{&options.hematocrit, "--hematocrit", "suspension.hematocrit"},
        std::tuple{&options.mix, "--mix", "suspension.mix"},
        std::tuple{&options.diameter_um, "--diameter-um", "suspension.tube_diameter_um"},
        std::tuple{&options.length_um, "--length-um", "suspension.tube_length_um"}}) {
    if (*value) assign_option(request, option, path, **value);
  }
  return request;
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

void print_ensemble(const nlohmann::ordered_json& ensemble) {
  const auto& statistics = ensemble["statistics"];
  std::printf("ensemble of %d orientations (seed %d), %d passed:\n",
              ensemble["orientations"].get<int>(), ensemble["seed"].get<int>(),
              ensemble["passed"].get<int>());
  for (const char* key :
       {"transit_time_s", "whole_cell_transit_time_s", "peak_deformation_index"}) {
    const auto& s = statistics[key];
    std::printf("  %-26s mean %.6g, standard deviation %.3g (min %.6g, max %.6g)\n", key,
                s["mean"].get<double>(), s["standard_deviation"].get<double>(),
                s["min"].get<double>(), s["max"].get<double>());
  }
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

void write_table(const std::filesystem::path& directory, const cases::CapillaryRun& run) {
  std::vector<std::vector<double>> rows;
  for (const auto& sample : run.samples) rows.push_back(cases::capillary_table_row(sample));
  io::write_csv_file(directory / "capillary_timeseries.csv", cases::capillary_table_columns(),
                     rows);
}

void add_progress(coupling::CoupledSimulation& simulation, const Progress& progress,
                  const RunDirectory& directory, double time_scale) {
  simulation.add_observer(
      {"progress", kProgressIntervalSteps,
       [&progress, &directory, time_scale](const coupling::CoupledSimulation& s) {
         const double centroid_x_um = s.frame().to_um(s.cell(0).centroid_lu()).x();
         progress.update("capillary: step " + std::to_string(s.time_step()) + ", t = " +
                         format_significant(s.time_s() * time_scale) + " s, centroid x = " +
                         format_number(std::round(centroid_x_um * 100.0) / 100.0) + " um, " +
                         format_number(std::round(directory.elapsed_s())) + " s");
       }});
}

// What every orientation of the run shares.
struct CapillaryContext {
  const CapillaryOptions& options;
  const config::Config& config;     // the user's, recorded in config.json
  const config::Config& simulated;  // the compressed one the runs simulate
  const setup::CapillaryWall& wall;
  const setup::CapillaryCompression& compression;
  const cases::CapillarySettings& settings;
  const setup::CellMesh& cell;
  const RunDirectory& directory;
  const cases::CapillaryPhysics& physics;
};

// The "capillary" object of result.json for one run, its time scale included.
nlohmann::ordered_json result_section(const CapillaryContext& c, const cases::CapillaryRun& run) {
  auto section = cases::capillary_result_section(
      {c.wall.geometry, c.settings.cell_axis, c.physics.membrane.forces}, run);
  section["time_scale"] = {
      {"compressed", c.compression.factor != 1.0},
      {"factor", c.compression.factor},
      {"physical_reynolds_number", c.compression.physical_reynolds_number},
      {"simulated_reynolds_number", c.compression.simulated_reynolds_number},
      {"simulated_kinematic_viscosity_m2_per_s",
       c.compression.simulated_kinematic_viscosity_m2_per_s},
      {"simulated_inlet_velocity_m_per_s", c.compression.simulated_inlet_velocity_m_per_s}};
  return section;
}

// One release of `cell_mesh`, its files in `subdirectory` of the run directory ("" for a single
// release, orientation_<k> in an ensemble).
cases::CapillaryRun run_release(const CapillaryContext& c, const mesh::TriangleMesh& cell_mesh,
                                const std::filesystem::path& subdirectory, bool& started) {
  const auto output = c.directory.path() / subdirectory;
  const auto intervals = setup::snapshot_intervals_from(c.simulated, c.physics.units, output);
  const Progress progress(c.options.common);
  auto physics = c.physics;  // an instability's dump goes to this release's directory
  physics.coupling.run_directory = output;
  auto run = cases::run_capillary(
      cell_mesh, physics, c.settings, [&](coupling::CoupledSimulation& simulation) {
        // Output observers before the checkpoint is wired: a resume restores their state.
        coupling::add_snapshot_output(simulation, output, intervals);
        add_progress(simulation, progress, c.directory, c.compression.factor);
        if (subdirectory.empty()) {
          // Before the directory is started: a refused checkpoint leaves no file behind.
          wire_checkpoints(simulation, c.options.checkpoint, c.directory, c.config);
        }
        if (!started) c.directory.start(c.config, c.cell);
        started = true;
        if (!subdirectory.empty()) {
          wire_checkpoints_in(subdirectory, simulation, c.options.checkpoint, c.directory,
                              c.config);
        }
      });
  progress.done();
  if (!started) c.directory.start(c.config, c.cell);
  started = true;
  std::filesystem::create_directories(output);
  setup::to_physical_units(run, c.compression);
  write_table(output, run);
  return run;
}

// The ensemble's statistics over the releases that passed, per observable (result.json
// "capillary_ensemble").
nlohmann::ordered_json ensemble_section(const std::vector<nlohmann::ordered_json>& sections,
                                        const std::vector<cases::ReleaseOrientation>& orientations,
                                        std::uint64_t seed) {
  auto releases = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < sections.size(); ++k) {
    const auto& s = sections[k];
    const auto& o = orientations[k];
    releases.push_back({{"index", k},
                        {"directory", "orientation_" + std::to_string(k)},
                        {"axis", {o.axis.x(), o.axis.y(), o.axis.z()}},
                        {"spin_rad", o.spin_rad},
                        {"passed", s["passed"]},
                        {"transit_time_s", s["transit_time_s"]},
                        {"whole_cell_transit_time_s", s["whole_cell_transit_time_s"]},
                        {"entry_time_s", s["entry_time_s"]},
                        {"exit_time_s", s["exit_time_s"]},
                        {"peak_deformation_index", s["peak_deformation_index"]}});
  }
  nlohmann::ordered_json statistics;
  for (const char* key : {"transit_time_s", "whole_cell_transit_time_s", "entry_time_s",
                          "exit_time_s", "peak_deformation_index"}) {
    std::vector<double> values;
    for (const auto& s : sections) {
      if (s["passed"].get<bool>() && s[key].is_number()) values.push_back(s[key].get<double>());
    }
    const auto spread = cases::spread_of(values);
    statistics[key] = {{"count", spread.count},
                       {"mean", spread.mean},
                       {"standard_deviation", spread.standard_deviation},
                       {"min", spread.min},
                       {"max", spread.max}};
  }
  std::size_t passed = 0;
  for (const auto& s : sections) passed += s["passed"].get<bool>() ? 1 : 0;
  return {{"orientations", sections.size()},
          {"seed", seed},
          {"passed", passed},
          {"statistics", statistics},
          {"releases", releases}};
}

// A finished release of an interrupted ensemble: its result.json's capillary object.
std::optional<nlohmann::ordered_json> finished_release(const std::filesystem::path& directory) {
  const auto file = directory / "result.json";
  if (!std::filesystem::exists(file)) return std::nullopt;
  std::ifstream in(file);
  const auto result = nlohmann::ordered_json::parse(in, nullptr, false);
  if (result.is_discarded() || result.value("status", "") == "interrupted") return std::nullopt;
  return result["capillary"];
}

void run_capillary_command(const CapillaryOptions& options) {
  const auto request = capillary_request(options);
  const auto config = config::resolve_config(request);
  if (wants_suspension(config)) {
    run_suspension_command(request, config, options.common, options.checkpoint);
    return;
  }
  const auto wall = setup::capillary_wall_from(config);
  // The run simulates the compressed configuration; config.json keeps the user's.
  const auto compression = setup::capillary_compression_from(config, wall);
  const auto simulated = setup::compressed_capillary_config(config, wall, compression);
  const auto settings = setup::capillary_settings_from(simulated, wall);
  auto cell_mesh = setup::cell_mesh_from(config);
  setup::add_resolution_notice(cell_mesh, config);
  setup::add_edge_spacing_notice(cell_mesh, config.number("lattice.spacing_um"));
  print_notices(cell_mesh.notices);
  const int count = config.integer("capillary.orientations");
  const auto seed = static_cast<std::uint64_t>(config.integer("capillary.orientation_seed"));
  const auto orientations = cases::release_orientations(count, seed);

  const RunDirectory directory("capillary", options.common, config);
  const auto physics =
      setup::capillary_physics_from(simulated, wall, cell_mesh.mesh, directory.path());
  const CapillaryContext context{options,  config,    simulated, wall,   compression,
                                 settings, cell_mesh, directory, physics};
  bool started = false;
  std::vector<nlohmann::ordered_json> sections;
  std::optional<cases::CapillaryRun> first;
  std::string failure;
  bool interrupted = false;
  for (int k = 0; k < count; ++k) {
    const std::filesystem::path subdirectory =
        count == 1 ? std::filesystem::path()
                   : std::filesystem::path("orientation_" + std::to_string(k));
    if (count > 1 && options.common.resuming) {
      if (auto done = finished_release(directory.path() / subdirectory)) {
        sections.push_back(std::move(*done));
        continue;
      }
    }
    auto run = run_release(context, cases::rotated(cell_mesh.mesh, orientations[k].rotation),
                           subdirectory, started);
    sections.push_back(result_section(context, run));
    if (count > 1) {
      auto result = run.interrupted ? directory.result_head_with_status("interrupted")
                                    : directory.result_head(run.ok());
      if (!run.ok()) result["failure"] = run.failure;
      result["headline"] = headline(run);
      result["capillary"] = sections.back();
      result["phase_ms_per_step"] = cases::phase_ms_per_step_json(run.phase_times);
      directory.write_json((subdirectory / "result.json").string(), result);
    }
    if (!first) first = run;
    if (!run.ok() && failure.empty()) {
      failure =
          (count > 1 ? "orientation " + std::to_string(k) + ": " : std::string()) + run.failure;
    }
    if (run.interrupted) {
      interrupted = true;
      break;
    }
  }
  const auto& run = *first;
  auto result = interrupted ? directory.result_head_with_status("interrupted")
                            : directory.result_head(failure.empty());
  if (!failure.empty()) result["failure"] = failure;
  result["headline"] = headline(run);
  const std::string first_release = count == 1 ? "" : "orientation_0/";
  const auto format =
      setup::snapshot_format_from(context.simulated, directory.path() / first_release);
  result["files"] = {{"config", "config.json"},
                     {"timeseries", count == 1 ? "capillary_timeseries.csv"
                                               : "orientation_0/capillary_timeseries.csv"},
                     {"membrane", first_release + coupling::membrane_series_file(format, false)},
                     {"fluid", first_release + coupling::fluid_series_file(format)}};
  result["capillary"] = sections.front();
  result["phase_ms_per_step"] = cases::phase_ms_per_step_json(run.phase_times);
  if (count > 1) {
    result["capillary_ensemble"] = ensemble_section(sections, orientations, seed);
    const auto& statistics = result["capillary_ensemble"]["statistics"];
    result["headline"]["transit_time_mean_s"] = statistics["transit_time_s"]["mean"];
    result["headline"]["transit_time_standard_deviation_s"] =
        statistics["transit_time_s"]["standard_deviation"];
  }
  directory.write_json("result.json", result);

  if (options.common.json) {
    std::cout << result.dump(2) << '\n';
  } else if (!options.common.quiet) {
    print_summary(result, run, directory);
    if (count > 1) print_ensemble(result["capillary_ensemble"]);
  }
  if (interrupted) throw Interrupted("capillary: " + failure);
  if (!failure.empty()) throw RuntimeFailure("capillary: " + failure);
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
                   with_default("Built-in capillary: paper-validation (31.2 um, 10.2 um, throat "
                                "6.75 um) or paper-morphology (42 um, 10 um, throat 6.8 um)",
                                "capillary.geometry"))
      ->type_name("NAME");
  command
      ->add_option("--wall", options->wall_file,
                   "Wall surface (STL, fluid inside, lumen open along x) instead of the built-in "
                   "capillary; then give capillary.inlet_velocity_m_per_s and set "
                   "capillary.wall_repulsion_pN_per_um2=0")
      ->type_name("FILE.stl");
  command
      ->add_option("--orientations", options->orientations,
                   "Release the cell in N orientations (capillary.orientations; a seeded "
                   "Fibonacci set on the sphere, the first the configured one) and report the "
                   "transit's mean and spread")
      ->type_name("N");
  command
      ->add_option("--hematocrit", options->hematocrit,
                   with_default("With --geometry tube: pack cells to this tube hematocrit "
                                "(a suspension: apparent viscosity, discharge hematocrit, "
                                "cell-free layer)",
                                "suspension.hematocrit"))
      ->type_name("H");
  command
      ->add_option("--mix", options->mix,
                   "Morphologies of the suspension by number fraction, e.g. "
                   "discocyte=0.8,echinocyte-III=0.2 (suspension.mix; default: all of "
                   "--morphology)")
      ->type_name("NAME=F,...");
  command
      ->add_option("--diameter-um", options->diameter_um,
                   with_default("Diameter of the tube", "suspension.tube_diameter_um"))
      ->type_name("D");
  command
      ->add_option(
          "--length-um", options->length_um,
          with_default("Length of the tube, periodic along its axis", "suspension.tube_length_um"))
      ->type_name("L");
  add_common_options(command, options->common);
  add_checkpoint_options(command, options->checkpoint, options->common);
  command->callback([options] { run_capillary_command(*options); });
}

const bool registered = register_command({"capillary", 50, attach_capillary, true});

}  // namespace
}  // namespace rbcsim::cli::capillary_command
