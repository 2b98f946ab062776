// Run directories as the experiment commands write them (the run-directory contract), built by
// the tests from analytic curves: config.json (the real resolved config plus "run"), result.json
// and, for capillary runs, capillary_timeseries.csv.
#pragma once

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "membrane/parameters.hpp"
#include "support/files.hpp"

namespace rbcsim::testing {

inline std::vector<std::string> all_terms() { return membrane::paper_force_term_names(); }

// The paper's four-term model: without area difference and total curvature.
inline std::vector<std::string> four_terms() {
  std::vector<std::string> terms;
  for (const auto& term : all_terms()) {
    if (term != "area_difference" && term != "total_curvature") terms.push_back(term);
  }
  return terms;
}

struct FixtureRun {
  std::string command;
  std::string morphology = "discocyte";
  std::vector<std::string> forces = all_terms();
  nlohmann::json section = nlohmann::json::object();  // result.json's object named after command
  nlohmann::json headline = nlohmann::json::object();
  std::string status = "ok";
  double wall_time_s = 2.5;
  int threads = 2;
  std::string time_series_csv = {};  // capillary_timeseries.csv when not empty
  // Merged into config.json (RFC 7386 merge patch), e.g. {"membrane": {"k_link_kBT": 3}}.
  nlohmann::json config_patch = nlohmann::json::object();
  std::vector<std::string> notices = {};  // config.json run.notices
  // The name of result.json's object for the command's results when not the command's own (a
  // suspension is a capillary run with a "suspension" object).
  std::string section_name = {};
  std::map<std::string, std::string> files = {};  // further files: name -> contents
};

inline std::filesystem::path write_run(const std::filesystem::path& directory,
                                       const FixtureRun& run) {
  std::filesystem::create_directories(directory);
  static const auto resolved = config::config_with_derived_values(config::resolve_config({}));
  auto configuration = resolved;
  configuration["morphology"] = run.morphology;
  configuration["membrane"]["forces"] = run.forces;
  configuration.merge_patch(run.config_patch);
  configuration["run"] = {{"command", run.command},
                          {"version", RBCSIM_VERSION},
                          {"mesh_source", "built-in " + run.morphology},
                          {"mesh_sha256", std::string(64, 'a')},
                          {"threads", run.threads},
                          {"started_utc", "2024-05-01T12:00:00Z"},
                          {"notices", run.notices}};
  nlohmann::json result = {
      {"command", run.command},
      {"version", RBCSIM_VERSION},
      {"morphology", run.morphology},
      {"status", run.status},
      {"wall_time_s", run.wall_time_s},
      {"threads", run.threads},
      {"headline", run.headline},
      {"files", nlohmann::json::object()},
      {run.section_name.empty() ? run.command : run.section_name, run.section}};
  write_file(directory / "config.json", configuration.dump(2));
  write_file(directory / "result.json", result.dump(2));
  if (!run.time_series_csv.empty()) {
    write_file(directory / "capillary_timeseries.csv", run.time_series_csv);
  }
  for (const auto& [name, contents] : run.files) write_file(directory / name, contents);
  return directory;
}

// The 13 forces of Mills et al. (2004), rounded.
inline const std::vector<double> kStretchForces_pN{0,  16,  19,  31,  38,  47, 68,
                                                   88, 109, 131, 151, 172, 193};

// A cell that stiffens with force: saturating exponentials with length scale `softness_pN`.
inline FixtureRun stretch_run(const std::vector<std::string>& forces, double softness_pN,
                              double rms_axial_um) {
  FixtureRun run{.command = "stretch"};
  run.forces = forces;
  auto points = nlohmann::json::array();
  for (const double force_pN : kStretchForces_pN) {
    points.push_back({{"force_pN", force_pN},
                      {"axial_um", 7.8 + 8.0 * (1 - std::exp(-force_pN / softness_pN))},
                      {"transverse_um", 7.8 - 3.4 * (1 - std::exp(-force_pN / softness_pN))},
                      {"converged", true},
                      {"iterations", 400}});
  }
  run.section = {{"mode", "quasi-static"},
                 {"forces_terms", forces},
                 {"points", points},
                 {"comparison",
                  {{"reference", "mills2004"},
                   {"rms_axial_um", rms_axial_um},
                   {"rms_transverse_um", 0.25},
                   {"inside_error_bars", 11},
                   {"point_count", 13}}}};
  run.headline = {{"axial_at_max_force_um", points.back()["axial_um"]},
                  {"rms_axial_um", rms_axial_um}};
  return run;
}

// Length grows linearly with shear rate to `length_at_2000_um`; breadth shrinks as much.
inline FixtureRun shear_run(const std::string& morphology, const std::vector<std::string>& forces,
                            double length_at_2000_um) {
  FixtureRun run{.command = "shear", .morphology = morphology, .forces = forces};
  auto rates = nlohmann::json::array();
  for (const double rate : {0.0, 500.0, 1000.0, 1500.0, 2000.0}) {
    const double stretch_um = (length_at_2000_um - 7.8) * rate / 2000;
    const double length_um = 7.8 + stretch_um;
    const double breadth_um = 7.8 - stretch_um / 2;
    rates.push_back({{"shear_rate_per_s", rate},
                     {"length_um", length_um},
                     {"breadth_um", breadth_um},
                     {"deformation_index", (length_um - breadth_um) / (length_um + breadth_um)},
                     {"inclination_deg", 45 - rate / 100},
                     {"tank_treading_hz", rate / (4 * std::numbers::pi)},
                     {"smoothness_rad", 0.05 + rate * 1e-5},
                     {"roughness_rad", 0.01 + rate * 1e-6},
                     {"steady", true}});
  }
  run.section = {{"rates", rates}};
  run.headline = {{"length_at_max_rate_um", length_at_2000_um}};
  return run;
}

// DI rises from 1 to `peak` at the throat (t = transit_time_s) and falls back: a Gaussian bump.
inline FixtureRun capillary_run(const std::string& morphology, double transit_time_s,
                                double peak_deformation_index,
                                const std::string& geometry = "paper-morphology") {
  FixtureRun run{.command = "capillary", .morphology = morphology};
  run.time_series_csv = "time_s,centroid_x_um,velocity_x_m_per_s,deformation_index\n";
  for (int step = 0; step <= 40; ++step) {
    const double time_s = 2 * transit_time_s * step / 40;
    const double bump = std::exp(-std::pow((time_s - transit_time_s) / (0.2 * transit_time_s), 2));
    run.time_series_csv += std::to_string(time_s) + "," + std::to_string(31.2 * step / 40) + "," +
                           std::to_string(0.04) + "," +
                           std::to_string(1 + (peak_deformation_index - 1) * bump) + "\n";
  }
  run.section = {{"geometry", geometry},
                 {"transit_time_s", transit_time_s},
                 {"peak_deformation_index", peak_deformation_index},
                 {"final_deformation_index", 1.0},
                 {"reynolds_number", 0.04},
                 {"capillary_number", 0.1}};
  run.headline = {{"transit_time_s", transit_time_s}};
  return run;
}

inline FixtureRun capillary_run_with_terms(const std::string& morphology,
                                           const std::vector<std::string>& forces,
                                           double peak_deformation_index,
                                           const std::string& geometry) {
  auto run = capillary_run(morphology, 0.6e-3, peak_deformation_index, geometry);
  run.forces = forces;
  return run;
}

// Cells of one morphology in a suspension: how many, and the radius their centres keep.
struct SuspendedCells {
  std::string morphology;
  int count;
  double centre_radius_um;
};

// A suspension in a straight tube (capillary --geometry tube --hematocrit) run for 1 ms and
// averaged over its second half, its cells carried 30 tube diameters (a developed flow, as the
// report asks before it compares): result.json's "suspension" object with the given averages,
// suspension_timeseries.csv relaxing to them, and cells_timeseries.csv with every cell's centre
// at its morphology's radius.
inline FixtureRun suspension_run(double diameter_um, double packed_hematocrit,
                                 double discharge_hematocrit, double relative_viscosity,
                                 const std::vector<SuspendedCells>& cells) {
  FixtureRun run{.command = "capillary", .section_name = "suspension"};
  const double tube_hematocrit = 0.8 * discharge_hematocrit;
  const double layer_um = 2.0;
  auto counts = nlohmann::json::object();
  auto names = nlohmann::json::array();
  int total = 0;
  for (const auto& kind : cells) {
    counts[kind.morphology] = kind.count;
    names.push_back(kind.morphology);
    total += kind.count;
  }
  run.section = {{"geometry", "tube"},
                 {"tube_diameter_um", diameter_um},
                 {"tube_length_um", 40.0},
                 {"cells", total},
                 {"cells_per_morphology", counts},
                 {"morphologies", names},
                 {"packed_hematocrit", packed_hematocrit},
                 {"pseudo_shear_rate_per_s", 100.0},
                 {"averaging_samples", 5},
                 {"relative_apparent_viscosity", relative_viscosity},
                 {"relative_apparent_viscosity_sd", 0.01},
                 {"tube_hematocrit", tube_hematocrit},
                 {"discharge_hematocrit", discharge_hematocrit},
                 {"tube_to_discharge_hematocrit", 0.8},
                 {"cell_free_layer_um", layer_um},
                 {"samples_with_pierced_cells", 0},
                 {"force_capped_steps", 0},
                 {"time_s", 1e-3},
                 {"cell_travel_um", 30.0 * diameter_um},
                 {"cell_travel_tube_diameters", 30.0}};
  run.headline = {{"relative_apparent_viscosity", relative_viscosity}};
  run.config_patch = {{"suspension", {{"averaging_fraction", 0.5}}}};
  std::string flow =
      "time_s,relative_apparent_viscosity,tube_hematocrit,discharge_hematocrit,"
      "cell_free_layer_um\n";
  std::string centres = "time_s,cell_id,morphology_index,radial_position_um\n";
  for (int sample = 0; sample <= 10; ++sample) {
    const double time_s = 1e-4 * sample;
    const double settled = 1.0 - std::exp(-sample / 2.0);
    flow += std::to_string(time_s) + "," +
            std::to_string(1.0 + (relative_viscosity - 1.0) * settled) + "," +
            std::to_string(tube_hematocrit) + "," + std::to_string(discharge_hematocrit) + "," +
            std::to_string(layer_um * settled) + "\n";
    int cell = 0;
    for (std::size_t m = 0; m < cells.size(); ++m) {
      for (int i = 0; i < cells[m].count; ++i, ++cell) {
        centres += std::to_string(time_s) + "," + std::to_string(cell) + "," + std::to_string(m) +
                   "," + std::to_string(cells[m].centre_radius_um) + "\n";
      }
    }
  }
  run.files = {{"suspension_timeseries.csv", flow}, {"cells_timeseries.csv", centres}};
  return run;
}

inline FixtureRun calibrate_run() {
  FixtureRun run{.command = "calibrate"};
  run.section = {
      {"hexagonal",
       {{"E_s_uN_per_m", 29.7},
        {"mu_uN_per_m", 10.2},
        {"K_uN_per_m", 28.1},
        {"poisson_ratio", 0.467},
        {"k_link_kBT", 7.0},
        {"k_area_kBT", 5.0}}},
      {"two_triangle", {{"bending_modulus_J", 2.05e-19}, {"k_bend_kBT", 50.0}}},
      {"stretch_fit",
       {{"k_link_kBT", 3.3},
        {"comparison", {{"reference", "mills2004"}, {"rms_axial_um", 0.59}, {"point_count", 13}}}}},
      {"paper",
       {{"hexagonal", {{"E_s_uN_per_m", 29.85}, {"mu_uN_per_m", 10.15}, {"K_uN_per_m", 28.2}}},
        {"two_triangle", {{"bending_modulus_J", 2e-19}}}}}};
  run.headline = {{"E_s_uN_per_m", 29.7}};
  return run;
}

// The set of runs the report is made for: a calibration, stretching with and without the two new
// terms, shear sweeps of the three morphologies (two of them also without the new terms, as in
// the paper's Figs. 10-11), capillary transits of the three morphologies in the paper's order and
// the discocyte's through the validation tube, with and without the two new terms.
inline std::vector<std::filesystem::path> write_standard_runs(const std::filesystem::path& root) {
  return {
      write_run(root / "calibrate", calibrate_run()),
      write_run(root / "stretch-six", stretch_run(all_terms(), 90, 0.31)),
      write_run(root / "stretch-four", stretch_run(four_terms(), 60, 0.52)),
      write_run(root / "shear-disc", shear_run("discocyte", all_terms(), 11.0)),
      write_run(root / "shear-echi", shear_run("echinocyte-III", all_terms(), 10.5)),
      write_run(root / "shear-echi-four", shear_run("echinocyte-III", four_terms(), 12.0)),
      write_run(root / "shear-stom", shear_run("stomatocyte-II", all_terms(), 9.5)),
      write_run(root / "shear-stom-four", shear_run("stomatocyte-II", four_terms(), 11.5)),
      write_run(root / "capillary-disc", capillary_run("discocyte", 1.0e-3, 1.45)),
      write_run(root / "capillary-echi", capillary_run("echinocyte-III", 1.2e-3, 1.35)),
      write_run(root / "capillary-stom", capillary_run("stomatocyte-II", 1.5e-3, 1.25)),
      write_run(root / "capillary-disc-validation",
                capillary_run("discocyte", 0.6e-3, 2.0, "paper-validation")),
      write_run(root / "capillary-disc-validation-four",
                capillary_run_with_terms("discocyte", four_terms(), 2.1, "paper-validation")),
  };
}

}  // namespace rbcsim::testing
