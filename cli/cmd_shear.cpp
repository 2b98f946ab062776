// rbcsim shear: one cell in simple shear flow, swept over shear rates (paper §3.2): length,
// breadth, deformation index, inclination, tank-treading frequency, surface smoothness and
// mesh-scale roughness of the steady shape at each rate (paper Figs. 9-11).
// --hematocrit H: many cells sheared between walls, their relative viscosity at each rate
// (shear_suspension.hpp).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "cases/shear_output.hpp"
#include "command_registry.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common_options.hpp"
#include "coupling/snapshot.hpp"
#include "io/csv_table.hpp"
#include "io/pvd_collection.hpp"
#include "membrane/membrane_model.hpp"
#include "run_directory.hpp"
#include "setup/cell_from_config.hpp"
#include "setup/coupling_from_config.hpp"
#include "setup/membrane_from_config.hpp"
#include "setup/shear_from_config.hpp"
#include "shear_suspension.hpp"

namespace rbcsim::cli::shear_command {
namespace {

struct ShearOptions {
  CommonOptions common;
  CheckpointOptions checkpoint;
  std::optional<std::string> rates;
  std::optional<std::string> boundary;
  std::optional<double> max_strain;
  std::optional<std::string> hematocrit;
  std::optional<std::string> mix;
};

// The command's own options are --set assignments in disguise, so config.json records them.
config::ConfigRequest shear_request(const ShearOptions& options) {
  auto request = options.common.config;
  if (options.rates) {
    setup::shear_rates_from(*options.rates, "--rates");  // the range's own diagnostics
    assign_option(request, "--rates", "shear.rates_per_s", *options.rates);
  }
  if (options.boundary) assign_option(request, "--boundary", "shear.boundary", *options.boundary);
  if (options.max_strain) {
    assign_option(request, "--max-strain", "shear.max_strain", format_number(*options.max_strain));
  }
  if (options.hematocrit) {
    assign_option(request, "--hematocrit", "suspension.hematocrit", *options.hematocrit);
    // A suspension is sheared between walls (shear_suspension.hpp).
    if (!options.boundary) assign_option(request, "--hematocrit", "shear.boundary", "walls");
  }
  if (options.mix) assign_option(request, "--mix", "suspension.mix", *options.mix);
  return request;
}

std::string shape_file_name(std::size_t index) {
  std::array<char, 48> name{};
  std::snprintf(name.data(), name.size(), "shapes/shear_%03zu.vtp", index);
  return name.data();
}

constexpr const char* kHistoryFileName = "history.csv";

// Writes each rate's final shape, its point (what a resumed run keeps) and its shape history as it
// ends, from the thread that ran it, and reports progress.
class ShapeRecorder {
 public:
  ShapeRecorder(const RunDirectory& run, const config::Config& config, std::size_t rate_count,
                const Progress& progress)
      : run_(run),
        fingerprint_(config_fingerprint(config)),
        rate_count_(rate_count),
        progress_(progress) {}

  void operator()(std::size_t rate_index, const cases::ShearPoint& point,
                  const coupling::CoupledSimulation& simulation) {
    coupling::write_cell_snapshot(run_.path() / shape_file_name(rate_index), simulation, 0);
    const auto rate_path = run_.path() / cases::shear_rate_directory(rate_index);
    std::filesystem::create_directories(rate_path);
    write_finished_record(rate_path / kRatePointFileName, cases::shear_point_record(point),
                          fingerprint_);
    io::write_csv_file(rate_path / kHistoryFileName, cases::shear_history_columns(),
                       cases::shear_history_rows(point));
    const std::lock_guard lock(mutex_);
    ++finished_;
    progress_.update("shear: " + std::to_string(finished_) + "/" + std::to_string(rate_count_) +
                     " rates, last " + format_number(point.plan.shear_rate_per_s) + " 1/s in " +
                     std::to_string(point.steps) + " steps, " +
                     format_number(std::round(run_.elapsed_s())) + " s");
  }

 private:
  const RunDirectory& run_;
  std::string fingerprint_;
  std::size_t rate_count_;
  const Progress& progress_;
  std::mutex mutex_;
  std::size_t finished_ = 0;
};

std::vector<io::PvdEntry> shape_entries(const std::vector<cases::ShearPoint>& points) {
  std::vector<io::PvdEntry> entries;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].failure.empty()) {
      entries.push_back({points[i].plan.shear_rate_per_s, shape_file_name(i)});
    }
  }
  return entries;
}

// The highest rate that ran to its end; a failed rate's shape is the one it broke in, not a
// result. Failed rates are counted apart from the unsteady ones.
nlohmann::ordered_json headline(const std::vector<cases::ShearPoint>& points) {
  nlohmann::ordered_json numbers = nlohmann::ordered_json::object();
  const cases::ShearPoint* highest = nullptr;
  for (const auto& point : points) {
    if (!point.failure.empty()) continue;
    if (!highest || point.plan.shear_rate_per_s > highest->plan.shear_rate_per_s) highest = &point;
  }
  if (highest) {
    numbers["max_shear_rate_per_s"] = highest->plan.shear_rate_per_s;
    numbers["length_um_at_max_rate"] = highest->shape.length_um;
    numbers["deformation_index_at_max_rate"] = highest->shape.deformation_index;
  }
  const auto failed = std::count_if(points.begin(), points.end(),
                                    [](const auto& point) { return !point.failure.empty(); });
  numbers["unsteady_rate_count"] =
      std::count_if(points.begin(), points.end(), [](const auto& point) { return !point.steady; }) -
      failed;
  numbers["failed_rate_count"] = failed;
  return numbers;
}

void print_table(const nlohmann::ordered_json& result, const std::vector<cases::ShearPoint>& points,
                 const RunDirectory& directory, bool verbose) {
  const auto& section = result["shear"];
  std::printf("%s",
              summary_heading("shear", section["boundary"].get<std::string>(), result).c_str());
  std::printf("\n%8s %10s %8s %8s %9s %8s %10s %6s %8s %8s %10s %9s %7s %7s", "rate_1/s",
              "sim_rate", "Re", "Ca", "length_um", "swing_um", "breadth_um", "DI", "incl_deg",
              "tt_hz", "smooth_rad", "rough_rad", "strain", "steady");
  if (verbose) std::printf(" %8s %10s %s", "steps", "wall_s", "stop");
  std::printf("\n");
  for (const auto& point : points) {
    const auto& plan = point.plan;
    std::printf(
        "%8.0f %10.4g %8.3g %8.3g %9.4f %8.4f %10.4f %6.3f %8.2f %8.3g %10.4f %9.4f %7.1f %7s",
        plan.shear_rate_per_s, plan.simulated_shear_rate_per_s, plan.reynolds_number,
        plan.capillary_number, point.shape.length_um, point.length_swing_um, point.shape.breadth_um,
        point.shape.deformation_index, point.shape.inclination_deg, point.tank_treading_hz,
        point.smoothness_rad, point.roughness_rad, point.strain,
        !point.failure.empty() ? "FAILED" : (point.steady ? "yes" : "NO"));
    if (verbose) {
      std::printf(" %8zu %10.2f %s", point.steps, point.wall_time_s,
                  point.failure.empty() ? point.stop_reason.c_str() : point.failure.c_str());
    }
    std::printf("\n");
  }
  std::printf("wall time %.1f s, %d thread(s); run directory %s\n", directory.elapsed_s(),
              directory.threads(), directory.path().c_str());
}

void write_table(const RunDirectory& directory, const std::vector<cases::ShearPoint>& points) {
  std::vector<std::vector<double>> rows;
  for (const auto& point : points) rows.push_back(cases::shear_table_row(point));
  io::write_csv_file(directory.path() / "shear.csv", cases::shear_table_columns(), rows);
}

std::string failures(const std::vector<cases::ShearPoint>& points) {
  std::string text;
  for (const auto& point : points) {
    if (point.failure.empty()) continue;
    text.append(text.empty() ? "" : "; ")
        .append("rate " + format_number(point.plan.shear_rate_per_s) + " 1/s: " + point.failure);
  }
  return text;
}

// With --resume: the points of the rates that had ended (rate_<i>/point.json), refused if written
// with another config.
std::vector<std::optional<cases::ShearPoint>> completed_points(const ShearOptions& options,
                                                               const config::Config& config,
                                                               std::size_t rate_count) {
  std::vector<std::optional<cases::ShearPoint>> points(rate_count);
  if (options.checkpoint.resume_directory.empty()) return points;
  const auto fingerprint = config_fingerprint(config);
  for (std::size_t i = 0; i < rate_count; ++i) {
    const auto file =
        options.checkpoint.resume_directory / cases::shear_rate_directory(i) / kRatePointFileName;
    if (const auto record = read_finished_record(file, fingerprint)) {
      points[i] = cases::shear_point_from_record(*record, file.string());
    }
  }
  return points;
}

// The rates that ended: interrupted ones are left out of the results.
std::vector<cases::ShearPoint> ended_points(const std::vector<cases::ShearPoint>& points) {
  std::vector<cases::ShearPoint> ended;
  std::copy_if(points.begin(), points.end(), std::back_inserter(ended),
               [](const auto& point) { return !point.interrupted; });
  return ended;
}

void run_shear_command(const ShearOptions& options) {
  const auto request = shear_request(options);
  const auto config = config::resolve_config(request);
  if (wants_sheared_suspension(config)) {
    run_sheared_suspension_command(request, config, options.common, options.checkpoint);
    return;
  }
  const auto settings = setup::shear_settings_from(config);
  auto cell_mesh = setup::cell_mesh_from(config);
  const auto parameters = setup::cell_membrane_parameters_from(config, cell_mesh.mesh);
  setup::add_resolution_notice(cell_mesh, config);
  setup::add_edge_spacing_notice(cell_mesh, config.number("lattice.spacing_um"));
  print_notices(cell_mesh.notices);
  const auto cell = cases::in_shear_frame(cell_mesh.mesh);
  const membrane::MembraneModel model(cell, parameters);

  const RunDirectory directory("shear", options.common, config);
  const auto engine = setup::shear_engine_from(config, directory.path());
  setup::require_cell_fits_shear_box(cell, settings, engine);
  const auto plans = cases::plan_shear_rates(model, cell, engine, settings);
  cases::ShearHooks hooks;
  hooks.completed = completed_points(options, config, plans.size());
  // Started once the first rate's simulation is set up (or after the sweep if none was), so that
  // what only the simulation can refuse (a lattice with too few blocks for the processes) leaves
  // no run directory behind.
  std::once_flag started;
  const auto start = [&] { std::call_once(started, [&] { directory.start(config, cell_mesh); }); };
  const Progress progress(options.common);
  ShapeRecorder recorder(directory, config, plans.size(), progress);
  hooks.finished = std::ref(recorder);
  hooks.configure = [&](std::size_t rate_index, coupling::CoupledSimulation& simulation) {
    start();
    wire_checkpoints_in(cases::shear_rate_directory(rate_index), simulation, options.checkpoint,
                        directory, config);
  };
  const auto all_points =
      cases::run_shear_sweep(model, cell, engine, settings, plans, directory.threads(), hooks);
  start();
  progress.done();
  const auto points = ended_points(all_points);
  const bool interrupted = points.size() < all_points.size();

  write_table(directory, points);
  io::write_pvd_collection(directory.path() / "shear.pvd", shape_entries(points));
  const auto failure = failures(points);
  auto result = interrupted ? directory.result_head_with_status("interrupted")
                            : directory.result_head(failure.empty());
  if (!failure.empty()) result["failure"] = failure;
  result["headline"] = headline(points);
  result["files"] = {{"config", "config.json"}, {"table", "shear.csv"}, {"shapes", "shear.pvd"}};
  result["shear"] = cases::shear_result_section(settings, parameters.forces, points);
  directory.write_json("result.json", result);

  if (options.common.json) {
    std::cout << result.dump(2) << '\n';
  } else if (!options.common.quiet) {
    print_table(result, points, directory, options.common.verbose);
  }
  if (interrupted) {
    throw Interrupted("shear: interrupted after " + std::to_string(points.size()) + " of " +
                      std::to_string(all_points.size()) + " rates");
  }
  if (!failure.empty()) throw RuntimeFailure("shear: " + failure);
}

void attach_shear(CLI::App& application) {
  auto options = std::make_shared<ShearOptions>();
  auto* command = application.add_subcommand(
      "shear",
      "One cell in simple shear flow: length, breadth, deformation index, inclination and "
      "tank-treading frequency vs shear rate (Bessis & Mohandas 1975)");
  command
      ->add_option(
          "--rates", options->rates,
          with_default("Shear rates in 1/s: a range list, e.g. 0:2000 (5 rates), 0:2000:250, "
                       "0:2000/9, 0,1000,2000; with --threads N, N rates run at once",
                       "shear.rates_per_s"))
      ->type_name("RANGE");
  command
      ->add_option("--boundary", options->boundary,
                   with_default("lees-edwards (sliding periodic images) or walls (moving walls)",
                                "shear.boundary"))
      ->type_name("KIND");
  command
      ->add_option("--max-strain", options->max_strain,
                   with_default("Strain (rate x time) after which a rate that is not steady is "
                                "reported steady: false",
                                "shear.max_strain"))
      ->type_name("STRAIN");
  command
      ->add_option("--hematocrit", options->hematocrit,
                   with_default("Pack cells to this hematocrit between two sliding walls (a "
                                "suspension: its relative viscosity at each rate; implies "
                                "--boundary walls)",
                                "suspension.hematocrit"))
      ->type_name("H");
  command
      ->add_option("--mix", options->mix,
                   "Morphologies of the suspension by number fraction, e.g. "
                   "discocyte=0.8,echinocyte-III=0.2 (suspension.mix; default: all of "
                   "--morphology)")
      ->type_name("NAME=F,...");
  add_common_options(command, options->common);
  add_checkpoint_options(command, options->checkpoint, options->common);
  command->callback([options] { run_shear_command(*options); });
}

const bool registered = register_command({"shear", 40, attach_shear, true});

}  // namespace
}  // namespace rbcsim::cli::shear_command
