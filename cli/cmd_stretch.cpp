// rbcsim stretch: the optical-tweezers experiment (paper §3.1): axial and transverse diameters
// of the cell against the pulling force, compared with Mills et al. (2004).
#include <CLI/CLI.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cases/json_values.hpp"
#include "cases/stretch_output.hpp"
#include "command_registry.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common_options.hpp"
#include "io/csv_table.hpp"
#include "io/pvd_collection.hpp"
#include "membrane/membrane_model.hpp"
#include "parallel/communicator.hpp"
#include "run_directory.hpp"
#include "setup/coupling_from_config.hpp"
#include "setup/membrane_from_config.hpp"
#include "setup/stretch_from_config.hpp"

namespace rbcsim::cli::stretch_command {
namespace {

struct StretchOptions {
  CommonOptions common;
  CheckpointOptions checkpoint;  // fluid mode only
  std::optional<std::string> mode;
  std::optional<std::string> forces;
  std::optional<double> contact_diameter_um;
};

// The command's own options are --set assignments in disguise, so config.json records them.
config::Config resolve_stretch_config(const StretchOptions& options) {
  auto common = options.common;
  auto& request = common.config;
  if (options.mode) assign_option(request, "--mode", "stretch.mode", *options.mode);
  if (options.forces) {
    setup::stretch_forces_from(*options.forces, "--forces");  // the range's own diagnostics
    assign_option(request, "--forces", "stretch.forces_pN", *options.forces);
  }
  if (options.contact_diameter_um) {
    assign_option(request, "--contact-diameter-um", "stretch.contact.rule", "contact-diameter");
    assign_option(request, "--contact-diameter-um", "stretch.contact.diameter_um",
                  format_number(*options.contact_diameter_um));
  }
  return resolve_config(common);
}

std::string shape_file_name(std::size_t index) {
  std::array<char, 48> name{};  // room for any index
  std::snprintf(name.data(), name.size(), "shapes/stretch_%03zu.vtp", index);
  return name.data();
}

// The work a force took: relaxation iterations (quasi-static) or time steps (fluid).
std::size_t effort_count(const cases::StretchPoint& point) {
  return point.steps > 0 ? point.steps : point.iterations;
}

std::string effort(const cases::StretchPoint& point) {
  return std::to_string(effort_count(point)) + (point.steps > 0 ? " steps" : " iterations");
}

// Writes each force's shape as it is reached (shapes/stretch_<point index>.vtp: a resumed run
// adds to the shapes of the points it keeps), and reports progress.
class ShapeRecorder {
 public:
  ShapeRecorder(const RunDirectory& run, const membrane::MembraneModel& model,
                std::size_t force_count, const Progress& progress)
      : run_(run), model_(model), force_count_(force_count), progress_(progress) {}

  void operator()(const cases::StretchState& state) {
    std::filesystem::create_directories(run_.path() / "shapes");
    cases::write_stretch_shape(run_.path() / shape_file_name(state.point_index), model_.triangles(),
                               state);
    progress_.update(
        "stretch: " + std::to_string(state.point_index + 1) + "/" + std::to_string(force_count_) +
        " forces, F = " + format_number(state.point.force_pN) + " pN, " + effort(state.point) +
        ", " + format_number(std::round(run_.elapsed_s())) + " s");
  }

 private:
  const RunDirectory& run_;
  const membrane::MembraneModel& model_;
  std::size_t force_count_;
  const Progress& progress_;
};

// Every point's shape is written (ShapeRecorder), the failed one's too.
std::vector<io::PvdEntry> shape_entries(const cases::StretchRun& run) {
  std::vector<io::PvdEntry> entries;
  for (std::size_t i = 0; i < run.points.size(); ++i) {
    entries.push_back({run.points[i].force_pN, shape_file_name(i)});
  }
  return entries;
}

// The quasi-static mode takes seconds and has no coupled simulation to checkpoint: it refuses
// the options rather than ignore them.
void require_fluid_mode_for_checkpoints(const StretchOptions& options,
                                        const cases::StretchSettings& settings) {
  if (settings.mode == "fluid") return;
  const auto& checkpoint = options.checkpoint;
  if (checkpoint.every.empty() && checkpoint.resume_directory.empty()) return;
  throw InputError(checkpoint.every.empty() ? "--resume" : "--checkpoint-every",
                   "only the fluid mode (--mode fluid) checkpoints; the " + settings.mode +
                       " mode takes seconds, run it again");
}

nlohmann::ordered_json headline(const cases::StretchRun& run,
                                const cases::StretchComparison& comparison) {
  nlohmann::ordered_json numbers = nlohmann::ordered_json::object();
  if (!run.points.empty()) {
    const auto& last = run.points.back();
    numbers["max_force_pN"] = last.force_pN;
    numbers["axial_um_at_max_force"] = last.axial_um;
    numbers["transverse_um_at_max_force"] = last.transverse_um;
  }
  if (comparison.rms_axial_um) numbers["rms_axial_vs_mills_um"] = *comparison.rms_axial_um;
  if (comparison.rms_transverse_um) {
    numbers["rms_transverse_vs_mills_um"] = *comparison.rms_transverse_um;
  }
  return numbers;
}

void print_table(const nlohmann::ordered_json& result, const cases::StretchRun& run,
                 const cases::StretchComparison& comparison, const RunDirectory& directory,
                 bool verbose) {
  const auto& section = result["stretch"];
  std::printf("%s", summary_heading("stretch", section["mode"].get<std::string>(), result).c_str());
  const bool fluid = section["mode"] == "fluid";
  std::printf("\n%10s %10s %15s %11s %10s", "force_pN", "axial_um", "transverse_um",
              fluid ? "steps" : "iterations", "converged");
  if (verbose) std::printf(" %18s %15s %12s", "residual_force_pN", "force_cap_hits", "wall_time_s");
  if (verbose && fluid) std::printf(" %16s %20s", "max_mach_number", "max_reynolds_number");
  std::printf("\n");
  for (const auto& point : run.points) {
    std::printf("%10.3f %10.4f %15.4f %11zu %10s", point.force_pN, point.axial_um,
                point.transverse_um, effort_count(point), point.converged ? "yes" : "NO");
    if (verbose) {
      std::printf(" %18.3g %15zu %12.2f", point.residual_force_pN, point.force_cap_hits,
                  point.wall_time_s);
    }
    if (verbose && fluid) {
      std::printf(" %16.3g %20.3g", point.max_mach_number, point.max_reynolds_number);
    }
    std::printf("\n");
  }
  if (comparison.point_count > 0) {
    std::printf(
        "vs Mills 2004 at %zu forces: RMS axial %.3f um, transverse %.3f um; inside the error "
        "bars: %zu (axial %zu, transverse %zu)\n",
        comparison.point_count, *comparison.rms_axial_um, *comparison.rms_transverse_um,
        comparison.inside_error_bars, comparison.axial_inside_error_bar,
        comparison.transverse_inside_error_bar);
  }
  std::printf("wall time %.1f s, %d thread(s); run directory %s\n", directory.elapsed_s(),
              directory.threads(), directory.path().c_str());
}

void write_table(const RunDirectory& directory, const cases::StretchRun& run) {
  std::vector<std::vector<double>> rows;
  for (const auto& point : run.points) rows.push_back(cases::stretch_table_row(point));
  io::write_csv_file(directory.path() / "stretch.csv", cases::stretch_table_columns(), rows);
}

// Under mpirun: only the fluid mode has a lattice to cut across processes.
void require_stretch_runs_across_processes(const config::Config& config) {
  if (parallel::Communicator::world().size() == 1) return;
  if (config.string("stretch.mode") != "fluid") {
    throw InputError("stretch.mode",
                     "the quasi-static stretch has no lattice to run across processes: run it on "
                     "one process (without mpirun), or use --mode fluid");
  }
}

void run_stretch_command(const StretchOptions& options) {
  const auto config = resolve_stretch_config(options);
  require_stretch_runs_across_processes(config);
  auto settings = setup::stretch_settings_from(config);
  require_fluid_mode_for_checkpoints(options, settings);
  auto cell_mesh = setup::cell_mesh_from(config);
  const auto parameters = setup::cell_membrane_parameters_from(config, cell_mesh.mesh);
  setup::add_resolution_notice(cell_mesh, config);
  if (settings.mode == "fluid")
    setup::add_edge_spacing_notice(cell_mesh, config.number("lattice.spacing_um"));
  print_notices(cell_mesh.notices);
  const auto cell = cases::prepare_stretch_cell(cell_mesh.mesh, settings.contact);
  const membrane::MembraneModel model(cell.mesh, parameters);
  setup::require_cell_fits_stretch_box(cell.mesh, settings);

  const RunDirectory directory("stretch", options.common, config);
  settings.fluid.output_directory = directory.path();
  // In fluid mode the directory is started once the simulation is set up and (with --resume) the
  // checkpoint accepted, so that a refused one, or a lattice with too few blocks for the
  // processes, leaves the run directory as it was.
  bool started = false;
  const auto start = [&] {
    if (!started) directory.start(config, cell_mesh);
    started = true;
  };
  if (settings.mode != "fluid") start();
  settings.fluid.configure = [&](coupling::CoupledSimulation& simulation) {
    wire_checkpoints(simulation, options.checkpoint, directory, config);
    start();
  };
  const Progress progress(options.common);
  ShapeRecorder recorder(directory, model, settings.forces_pN.size(), progress);
  const auto run = cases::run_stretch(model, cell, settings, std::ref(recorder));
  start();
  progress.done();

  const auto comparison =
      cases::compare_with_reference(run.points, setup::mills2004_stretch_reference());
  write_table(directory, run);
  io::write_pvd_collection(directory.path() / "stretch.pvd", shape_entries(run));
  auto result = directory.result_head_with_status(run.interrupted ? "interrupted"
                                                  : run.ok()      ? "ok"
                                                                  : "failed");
  if (!run.ok()) result["failure"] = run.failure;
  result["headline"] = headline(run, comparison);
  result["files"] = {
      {"config", "config.json"}, {"table", "stretch.csv"}, {"shapes", "stretch.pvd"}};
  if (std::filesystem::exists(directory.path() / "fluid.vti")) {
    result["files"]["fluid"] = "fluid.vti";
  }
  result["stretch"] =
      cases::stretch_result_section(settings.mode, parameters.forces, run.points, comparison);
  result["stretch"]["sub_spacing_drag"] = cases::sub_spacing_drag_json(run.sub_spacing_drag);
  directory.write_json("result.json", result);

  if (options.common.json) {
    std::cout << result.dump(2) << '\n';
  } else if (!options.common.quiet) {
    print_table(result, run, comparison, directory, options.common.verbose);
  }
  if (run.interrupted) throw Interrupted("stretch: " + run.failure);
  if (!run.ok()) throw RuntimeFailure("stretch: " + run.failure);
}

void attach_stretch(CLI::App& application) {
  auto options = std::make_shared<StretchOptions>();
  auto* command = application.add_subcommand(
      "stretch",
      "Optical-tweezers stretching: axial and transverse diameters vs force, compared with Mills "
      "et al. (2004)");
  command
      ->add_option("--mode", options->mode,
                   with_default("How each force reaches its steady shape: quasi-static (membrane "
                                "alone, no fluid) or fluid (in fluid at rest, LBM + IBM, to a "
                                "steady state)",
                                "stretch.mode"))
      ->type_name("MODE");
  command
      ->add_option("--forces", options->forces,
                   with_default("Total force per contact patch in pN: mills2004 (the 13 forces of "
                                "the reference) or a range list, e.g. 0:200:25, 0:200/9, 0,50,100",
                                "stretch.forces_pN"))
      ->type_name("RANGE");
  command
      ->add_option(
          "--contact-diameter-um", options->contact_diameter_um,
          with_default("Bead contact diameter in um: the patch is the vertices within half of "
                       "it from each end vertex",
                       "stretch.contact.diameter_um"))
      ->type_name("D");
  add_common_options(command, options->common);
  add_checkpoint_options(command, options->checkpoint, options->common);
  command->callback([options] { run_stretch_command(*options); });
}

const bool registered = register_command({"stretch", 30, attach_stretch, true});

}  // namespace
}  // namespace rbcsim::cli::stretch_command
