#include "shear_suspension.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cases/json_values.hpp"
#include "cases/shear_case.hpp"
#include "cases/shear_observables.hpp"
#include "cases/sheared_suspension.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/wall_clock.hpp"
#include "coupling/snapshot.hpp"
#include "io/csv_table.hpp"
#include "io/pvd_collection.hpp"
#include "mesh/geometry.hpp"
#include "report/reference_data.hpp"
#include "run_directory.hpp"
#include "setup/coupling_from_config.hpp"
#include "setup/shear_from_config.hpp"
#include "setup/suspension_from_config.hpp"

namespace rbcsim::cli {
// Named: the unity build merges this file with capillary_suspension.cpp's anonymous namespace.
namespace sheared_suspension_output {

constexpr std::size_t kShearProgressIntervalSteps = 500;

// The largest vertex distance of any morphology: the box's reference length (as one cell's in
// shear, shear.gap_diameters and shear.width_diameters).
double reference_diameter_um(const std::vector<cases::SuspensionMorphology>& morphologies) {
  double diameter_um = 0.0;
  for (const auto& morphology : morphologies) {
    diameter_um =
        std::max(diameter_um, cases::largest_vertex_distance_um(morphology.mesh.positions_um));
  }
  return diameter_um;
}

// A length as the case rounds it to the lattice (sheared_suspension.cpp).
double rounded_um(double length_um, double dx_um) {
  return std::max(1.0, std::round(length_um / dx_um)) * dx_um;
}

double gap_volume_um3(const cases::ShearedSuspensionSettings& settings, double dx_um) {
  return rounded_um(settings.gap_um, dx_um) * rounded_um(settings.length_um, dx_um) *
         rounded_um(settings.width_um, dx_um);
}

// One rate as run, with the time scale it ran at.
struct RatePoint {
  double shear_rate_per_s = 0.0;
  setup::SuspensionCompression compression;
  cases::ShearedSuspensionRun run;
};

std::vector<std::string> sample_columns() {
  return {"time_s",
          "strain",
          "relative_viscosity",
          "particle_stress_Pa",
          "cytoplasm_stress_Pa",
          "near_wall_relative_viscosity",
          "contact_pairs",
          "pierced_cells"};
}

std::vector<std::string> cell_columns() {
  return {"time_s", "cell", "morphology", "x_um", "y_um", "z_um", "deformation_index"};
}

std::vector<std::string> rate_columns() {
  return {"shear_rate_per_s",
          "simulated_shear_rate_per_s",
          "reynolds_number",
          "relative_viscosity",
          "relative_viscosity_sd",
          "near_wall_relative_viscosity",
          "averaged_samples",
          "strain",
          "samples_with_pierced_cells",
          "ok"};
}

std::vector<double> rate_row(const RatePoint& point) {
  const auto& run = point.run;
  return {point.shear_rate_per_s,
          point.shear_rate_per_s * point.compression.factor,
          point.compression.physical_reynolds_number,
          run.relative_viscosity,
          run.relative_viscosity_sd,
          run.near_wall_relative_viscosity,
          static_cast<double>(run.averaged_samples),
          run.samples.empty() ? 0.0 : run.samples.back().strain,
          static_cast<double>(run.samples_with_pierced_cells),
          run.ok() ? 1.0 : 0.0};
}

void write_rate_tables(const std::filesystem::path& directory, const RatePoint& point) {
  std::vector<std::vector<double>> rows;
  for (const auto& s : point.run.samples) {
    rows.push_back({s.time_s, s.strain, s.relative_viscosity, s.particle_stress_Pa,
                    s.cytoplasm_stress_Pa, s.near_wall_relative_viscosity,
                    static_cast<double>(s.contact_pairs), static_cast<double>(s.pierced_cells)});
  }
  io::write_csv_file(directory / "suspension_timeseries.csv", sample_columns(), rows);
  rows.clear();
  for (const auto& s : point.run.cell_samples) {
    rows.push_back({s.time_s, static_cast<double>(s.cell),
                    static_cast<double>(point.run.cell_morphologies.at(s.cell)), s.centroid_um.x(),
                    s.centroid_um.y(), s.centroid_um.z(), s.deformation_index});
  }
  io::write_csv_file(directory / "cells_timeseries.csv", cell_columns(), rows);
}

// Times back to physical ones (x s); strains, stresses and ratios are the same at equal Ca.
void to_physical_times(cases::ShearedSuspensionRun& run, double factor) {
  for (auto& sample : run.samples) sample.time_s *= factor;
  for (auto& sample : run.cell_samples) sample.time_s *= factor;
  run.time_s *= factor;
}

nlohmann::ordered_json rate_json(const RatePoint& point, std::size_t index) {
  const auto& run = point.run;
  nlohmann::ordered_json json = {
      {"shear_rate_per_s", point.shear_rate_per_s},
      {"directory", cases::shear_rate_directory(index)},
      {"simulated_shear_rate_per_s", point.shear_rate_per_s * point.compression.factor},
      {"time_scale",
       {{"compressed", point.compression.factor != 1.0},
        {"factor", point.compression.factor},
        {"physical_reynolds_number", point.compression.physical_reynolds_number},
        {"simulated_reynolds_number", point.compression.simulated_reynolds_number}}},
      {"gap_um", run.gap_um},
      {"length_um", run.length_um},
      {"width_um", run.width_um},
      {"cells", run.cell_morphologies.size()},
      {"hematocrit", run.packed_hematocrit},
      {"packing_iterations", run.packing_iterations},
      {"plasma_stress_Pa", run.plasma_stress_Pa},
      {"relative_viscosity", run.relative_viscosity},
      {"relative_viscosity_sd", run.relative_viscosity_sd},
      {"pries1992_large_tube_relative_viscosity",
       report::pries1992_large_tube_relative_viscosity(run.packed_hematocrit)},
      {"near_wall_relative_viscosity", run.near_wall_relative_viscosity},
      {"averaged_samples", run.averaged_samples},
      {"steps", run.steps},
      {"time_s", run.time_s},
      {"strain", run.samples.empty() ? 0.0 : run.samples.back().strain},
      {"close_contact_steps", run.close_contact_steps},
      {"capped_contact_steps", run.capped_contact_steps},
      {"samples_with_pierced_cells", run.samples_with_pierced_cells},
      {"sub_spacing_drag", cases::sub_spacing_drag_json(run.sub_spacing_drag)},
      {"stop_reason", run.stop_reason}};
  if (!run.ok()) json["failure"] = run.failure;
  return json;
}

// A rate that ran to its end (or failed in its physics): kept in rate_<i>/point.json with the
// config's fingerprint, so that --resume of a sweep does not run it again.
void write_finished_rate(const std::filesystem::path& rate_path, const RatePoint& point,
                         const std::string& fingerprint) {
  const nlohmann::ordered_json record = {
      {"shear_rate_per_s", point.shear_rate_per_s},
      {"time_scale",
       {{"factor", point.compression.factor},
        {"physical_reynolds_number", point.compression.physical_reynolds_number},
        {"simulated_reynolds_number", point.compression.simulated_reynolds_number}}},
      {"run", cases::sheared_suspension_record(point.run)}};
  write_finished_record(rate_path / kRatePointFileName, record, fingerprint);
}

// With --resume: rate `index` as it ended before, if it did (InputError if its record was
// written under another config or cannot be read).
std::optional<RatePoint> finished_rate(const CheckpointOptions& checkpoint, std::size_t index,
                                       const std::string& fingerprint) {
  if (checkpoint.resume_directory.empty()) return std::nullopt;
  const auto file =
      checkpoint.resume_directory / cases::shear_rate_directory(index) / kRatePointFileName;
  const auto found = read_finished_record(file, fingerprint);
  if (!found) return std::nullopt;
  const auto& record = *found;
  const auto source = file.string();
  if (!record.contains("time_scale") || !record.contains("run")) {
    throw InputError(source, "no \"time_scale\" or \"run\"");
  }
  RatePoint point;
  point.shear_rate_per_s = cases::record_number(record, "shear_rate_per_s", source);
  const auto& scale = record.at("time_scale");
  point.compression = {cases::record_number(scale, "factor", source),
                       cases::record_number(scale, "physical_reynolds_number", source),
                       cases::record_number(scale, "simulated_reynolds_number", source)};
  point.run = cases::sheared_suspension_from_record(record.at("run"), source);
  return point;
}

void print_summary(const std::vector<RatePoint>& points, const setup::SuspensionMix& mix,
                   const RunDirectory& directory) {
  std::string names;
  for (const auto& name : mix.names) names += (names.empty() ? "" : ", ") + name;
  const auto& first = points.front().run;
  std::printf("shear (suspension between walls), %s\n", names.c_str());
  std::printf("gap %.4g um, box %.4g x %.4g um (periodic), %zu cells, hematocrit %.4f\n",
              first.gap_um, first.length_um, first.width_um, first.cell_morphologies.size(),
              first.packed_hematocrit);
  std::printf(
      "high-shear bulk blood at this hematocrit (Pries et al. 1992, wide-tube limit): "
      "relative viscosity %.4f\n",
      report::pries1992_large_tube_relative_viscosity(first.packed_hematocrit));
  std::printf("%10s %10s %9s %10s %9s %10s %8s %s\n", "rate_1/s", "sim_rate", "Re", "rel_visc",
              "sd", "near_wall", "strain", "status");
  for (const auto& point : points) {
    const auto row = rate_row(point);
    std::printf("%10.4g %10.4g %9.3g %10.4f %9.3g %10.4f %8.2f %s\n", row[0], row[1], row[2],
                row[3], row[4], row[5], row[7], point.run.ok() ? "ok" : point.run.failure.c_str());
  }
  std::printf("wall time %.1f s, %d thread(s); run directory %s\n", directory.elapsed_s(),
              directory.threads(), directory.path().c_str());
}

}  // namespace sheared_suspension_output

using namespace sheared_suspension_output;

bool wants_sheared_suspension(const config::Config& config) {
  const bool hematocrit = config.number("suspension.hematocrit") > 0.0;
  const bool placed = !config.cell_list("suspension.cells").empty();
  if (hematocrit && placed) {
    throw InputError("suspension.cells",
                     "cells placed by hand and --hematocrit exclude each other: give one");
  }
  if (!hematocrit && !placed) return false;
  if (config.string("shear.boundary") != "walls") {
    throw InputError("shear.boundary",
                     "a sheared suspension runs between walls (--boundary walls): cells crossing "
                     "a Lees-Edwards plane are not supported");
  }
  return true;
}

void run_sheared_suspension_command(const config::ConfigRequest& request,
                                    const config::Config& config, const CommonOptions& common,
                                    const CheckpointOptions& checkpoint) {
  const auto rates = setup::shear_settings_from(config).rates_per_s;
  for (const double rate : rates) {
    if (!(rate > 0.0)) {
      throw InputError("shear.rates_per_s",
                       "a sheared suspension's rates must be > 0 (its viscosity is a stress over "
                       "a rate), got " +
                           format_number(rate) + "; give --rates, e.g. --rates 200,1000");
    }
  }
  const auto mix = setup::suspension_mix_from(config);
  std::vector<std::string> import_notices;
  const auto physical_morphologies =
      setup::suspension_morphologies_from(request, mix, 1.0, &import_notices);
  print_notices(import_notices);
  const double diameter_um = reference_diameter_um(physical_morphologies);
  const auto contact_notice = setup::contact_range_notice(config);
  const auto box = setup::sheared_suspension_settings_from(config, diameter_um, 1.0);
  const auto cells =
      box.placed_cells.empty()
          ? setup::packed_cell_kinds(physical_morphologies, mix,
                                     gap_volume_um3(box, config.number("lattice.spacing_um")),
                                     config.number("suspension.hematocrit"))
          : setup::placed_cell_kinds(mix, config.cell_list("suspension.cells"));
  const std::vector<std::int32_t> kinds(cells.begin(), cells.end());

  // Every rate's wall speed before anything runs, so that bad input leaves no run behind.
  for (const double rate : rates) {
    const double factor =
        setup::sheared_suspension_compression_from(config, rate, diameter_um).factor;
    const auto simulated = setup::compressed_suspension_config(config, factor);
    config::make_unit_converter(simulated).check_lattice_velocity(
        0.5 * rate * factor * rounded_um(box.gap_um, config.number("lattice.spacing_um")) * 1e-6,
        "shear.rates_per_s (" + format_number(rate) + " 1/s: the walls' speed, rate x gap / 2)");
    // Physical times: the growth must be over before this rate's averages start.
    cases::require_growth_before_window(
        box.packing.scale, config.number("suspension.growth_time_s"),
        (1.0 - box.averaging_fraction) * box.strain / rate, "suspension.strain");
  }

  const RunDirectory directory("shear", common, config);
  std::string names;
  for (const auto& name : mix.names) names += (names.empty() ? "" : ", ") + name;
  const setup::CellMesh described{
      physical_morphologies.front().mesh,
      "sheared suspension of " + std::to_string(cells.size()) + " cells (" + names + ")",
      {},
      {}};
  bool started = false;
  const Progress progress(common);
  std::vector<RatePoint> points;
  const auto fingerprint = config_fingerprint(config);
  for (std::size_t i = 0; i < rates.size(); ++i) {
    const auto rate_path = directory.path() / cases::shear_rate_directory(i);
    if (auto finished = finished_rate(checkpoint, i, fingerprint)) {
      if (!started) directory.start(config, described);
      started = true;
      write_rate_tables(rate_path, *finished);
      points.push_back(std::move(*finished));
      continue;
    }
    RatePoint point;
    point.shear_rate_per_s = rates[i];
    point.compression = setup::sheared_suspension_compression_from(config, rates[i], diameter_um);
    const double factor = point.compression.factor;
    const auto simulated = setup::compressed_suspension_config(config, factor);
    const auto morphologies = setup::suspension_morphologies_from(request, mix, factor);
    const auto settings =
        setup::sheared_suspension_settings_from(simulated, diameter_um, rates[i] * factor);
    const cases::SuspensionPhysics physics{setup::fluid_parameters_from(simulated),
                                           setup::coupling_parameters_from(simulated, rate_path),
                                           config::make_unit_converter(simulated)};
    const auto intervals = setup::snapshot_intervals_from(simulated, physics.units, rate_path);
    // This rate's own (it outlives the set-up callback below, which only registers the observer).
    WallTimeLeft time_left(settings.strain);
    point.run = cases::run_sheared_suspension(
        morphologies, cells, physics, settings, [&](coupling::CoupledSimulation& simulation) {
          std::filesystem::create_directories(rate_path);
          coupling::add_snapshot_output(simulation, rate_path, intervals, kinds);
          simulation.add_observer(
              {"progress", kShearProgressIntervalSteps, [&](const coupling::CoupledSimulation& s) {
                 const double strain = s.time_s() * settings.shear_rate_per_s;
                 const double wall_s = directory.elapsed_s();
                 const auto left = time_left.text(strain, wall_s);
                 progress.update("shear suspension: rate " + std::to_string(i + 1) + "/" +
                                 std::to_string(rates.size()) + ", step " +
                                 std::to_string(s.time_step()) + ", strain " +
                                 format_significant(strain) + " of " +
                                 format_significant(settings.strain) + ", " +
                                 format_number(std::round(wall_s)) + " s" +
                                 (left.empty() ? "" : left + " at this rate"));
               }});
          // After the output observers (a resume restores their state); with --resume, a rate
          // without a checkpoint had not started and starts afresh.
          wire_checkpoints_in(cases::shear_rate_directory(i), simulation, checkpoint, directory,
                              config);
          // Once the first rate's cells are packed (the same packing for every rate): bad input
          // is one line and no directory.
          if (!started) {
            if (contact_notice) print_notices(std::span(&*contact_notice, 1));
            directory.start(config, described);
            started = true;
          }
        });
    if (!started) directory.start(config, described);
    started = true;
    std::filesystem::create_directories(rate_path);
    to_physical_times(point.run, factor);
    write_rate_tables(rate_path, point);
    if (!point.run.interrupted) write_finished_rate(rate_path, point, fingerprint);
    points.push_back(std::move(point));
    if (points.back().run.interrupted) break;
  }
  progress.done();

  std::vector<std::vector<double>> rows;
  for (const auto& point : points) rows.push_back(rate_row(point));
  io::write_csv_file(directory.path() / "sheared_suspension.csv", rate_columns(), rows);
  std::string failure;
  bool interrupted = false;
  for (const auto& point : points) {
    interrupted = interrupted || point.run.interrupted;
    if (point.run.ok()) continue;
    failure.append(failure.empty() ? "" : "; ")
        .append("rate " + format_number(point.shear_rate_per_s) + " 1/s: " + point.run.failure);
  }
  auto result = interrupted ? directory.result_head_with_status("interrupted")
                            : directory.result_head(failure.empty());
  if (!failure.empty()) result["failure"] = failure;
  nlohmann::ordered_json section = {{"boundary", "walls"},
                                    {"morphologies", mix.names},
                                    {"reference_diameter_um", diameter_um},
                                    {"rates", nlohmann::ordered_json::array()}};
  for (std::size_t i = 0; i < points.size(); ++i)
    section["rates"].push_back(rate_json(points[i], i));
  result["sheared_suspension"] = section;
  nlohmann::ordered_json headline = nlohmann::ordered_json::object();
  headline["hematocrit"] = points.front().run.packed_hematocrit;
  for (const auto& point : points) {
    if (point.run.ok()) {
      headline["shear_rate_per_s"] = point.shear_rate_per_s;
      headline["relative_viscosity"] = point.run.relative_viscosity;
    }
  }
  result["headline"] = headline;
  const auto format =
      setup::snapshot_format_from(config, directory.path() / cases::shear_rate_directory(0));
  result["files"] = {{"config", "config.json"},
                     {"table", "sheared_suspension.csv"},
                     {"timeseries", "rate_<i>/suspension_timeseries.csv"},
                     {"cells", "rate_<i>/cells_timeseries.csv"},
                     {"membrane", "rate_<i>/" + coupling::membrane_series_file(format, true)},
                     {"fluid", "rate_<i>/" + coupling::fluid_series_file(format)}};
  directory.write_json("result.json", result);
  if (common.json) {
    std::cout << result.dump(2) << '\n';
  } else if (!common.quiet) {
    print_summary(points, mix, directory);
  }
  if (interrupted) throw Interrupted("shear: interrupted");
  if (!failure.empty()) throw RuntimeFailure("shear: " + failure);
}

}  // namespace rbcsim::cli
