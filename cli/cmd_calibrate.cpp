// rbcsim calibrate: the patch tests (paper §2.3): what the membrane's k parameters mean as
// moduli, and the k that give target moduli, written as a config file the other commands accept.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cases/calibration.hpp"
#include "cases/stretch_output.hpp"
#include "command_registry.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common_options.hpp"
#include "io/csv_table.hpp"
#include "run_directory.hpp"
#include "setup/calibrate_from_config.hpp"
#include "setup/membrane_from_config.hpp"

namespace rbcsim::cli::calibrate_command {
namespace {

struct CalibrateOptions {
  CommonOptions common;
  std::optional<std::string> fits;
  std::optional<double> shear_uN_per_m;
  std::optional<double> area_uN_per_m;
  std::optional<double> young_uN_per_m;
  std::optional<double> poisson_ratio;
  std::optional<double> bending_modulus_J;
  std::optional<double> overall_bending_modulus_J;
};

void assign_number(config::ConfigRequest& request, std::string_view option, std::string_view path,
                   const std::optional<double>& value) {
  if (value) assign_option(request, option, path, format_number(*value));
}

// The command's own options are --set assignments in disguise, so config.json records them.
config::Config resolve_calibrate_config(const CalibrateOptions& options) {
  auto common = options.common;
  auto& request = common.config;
  const bool shear_area = options.shear_uN_per_m || options.area_uN_per_m;
  const bool young_poisson = options.young_uN_per_m || options.poisson_ratio;
  if (shear_area && young_poisson) {
    throw InputError("--target-young-modulus",
                     "give the in-plane targets either as shear and area moduli or as Young's "
                     "modulus and Poisson ratio, not both");
  }
  if (shear_area) {
    assign_option(request,
                  options.shear_uN_per_m ? "--target-shear-modulus" : "--target-area-modulus",
                  "calibrate.target.moduli", "shear-area");
  }
  if (young_poisson) {
    assign_option(request,
                  options.young_uN_per_m ? "--target-young-modulus" : "--target-poisson-ratio",
                  "calibrate.target.moduli", "young-poisson");
  }
  if (options.fits) assign_option(request, "--fits", "calibrate.fits", *options.fits);
  assign_number(request, "--target-shear-modulus", "calibrate.target.shear_modulus_uN_per_m",
                options.shear_uN_per_m);
  assign_number(request, "--target-area-modulus", "calibrate.target.area_modulus_uN_per_m",
                options.area_uN_per_m);
  assign_number(request, "--target-young-modulus", "calibrate.target.young_modulus_uN_per_m",
                options.young_uN_per_m);
  assign_number(request, "--target-poisson-ratio", "calibrate.target.poisson_ratio",
                options.poisson_ratio);
  assign_number(request, "--target-bending-modulus", "calibrate.target.bending_modulus_J",
                options.bending_modulus_J);
  assign_number(request, "--target-overall-bending-modulus",
                "calibrate.target.overall_bending_modulus_J", options.overall_bending_modulus_J);
  return resolve_config(common);
}

nlohmann::ordered_json headline(const cases::Calibration& calibration) {
  const auto& network = calibration.hexagonal.network;
  nlohmann::ordered_json numbers = {
      {"E_s_uN_per_m", network.young_uN_per_m},
      {"mu_uN_per_m", network.shear_uN_per_m},
      {"K_uN_per_m", network.area_uN_per_m},
      {"poisson_ratio", network.poisson_ratio},
      {"bending_modulus_J", calibration.two_triangle.bending_modulus_J},
      {"overall_bending_modulus_J", calibration.overall_bending_modulus_J}};
  const auto fitted = cases::fitted_parameters_document(calibration);  // outlives the loop
  for (const auto& [key, value] : fitted["membrane"].items()) numbers["fitted_" + key] = value;
  return numbers;
}

// One row of a block: a number as such, a string (a reference's name) or null ("-") as text.
void print_quantity(const std::string& name, const nlohmann::ordered_json& value,
                    const std::string& paper_value) {
  if (value.is_number()) {
    std::printf("  %-32s %14.6g %14s\n", name.c_str(), value.get<double>(), paper_value.c_str());
    return;
  }
  const std::string text = value.is_string() ? value.get<std::string>() : "-";
  std::printf("  %-32s %14s %14s\n", name.c_str(), text.c_str(), paper_value.c_str());
}

// One block per patch test: quantity, rbcsim's value, the paper's; a group of quantities inside a
// test (the stretch fit's comparison with Mills) under its name, indented.
void print_table(const nlohmann::ordered_json& result, const cases::Calibration& calibration,
                 const RunDirectory& directory) {
  const auto& section = result["calibrate"];
  const auto& paper = section["paper"];
  std::printf("calibrate, %s (membrane distribution and kernel as configured)\n",
              result["morphology"].get<std::string>().c_str());
  for (const auto& [test, values] : section.items()) {
    if (test == "paper") continue;
    std::printf("\n%-34s %14s %14s\n", test.c_str(), "rbcsim", "paper");
    const auto paper_test = paper.find(test);
    for (const auto& [quantity, value] : values.items()) {
      if (value.is_object()) {
        std::printf("  %s\n", quantity.c_str());
        for (const auto& [member, member_value] : value.items()) {
          print_quantity("  " + member, member_value, "-");
        }
        continue;
      }
      std::string paper_value = "-";
      if (paper_test != paper.end() && paper_test->contains(quantity)) {
        paper_value = format_number((*paper_test)[quantity].get<double>());
      }
      print_quantity(quantity, value, paper_value);
    }
  }
  if (calibration.stretch) {
    const auto& contact = calibration.settings.stretch_fit.stretch.contact;
    std::printf(
        "\nstretch fit: %zu curves (stretch_fit.csv) against Mills et al. 2004, contact %s, "
        "%s\n",
        calibration.stretch->curve.evaluations.size(), contact.rule.c_str(),
        contact.rigid ? "rigid" : "free");
  }
  std::printf("\nfitted parameters: %s\nwall time %.2f s, %d thread(s); run directory %s\n",
              (directory.path() / "parameters.json").c_str(), directory.elapsed_s(),
              directory.threads(), directory.path().c_str());
}

void write_stretch_fit_table(const RunDirectory& directory, const cases::StretchFit& fit) {
  std::vector<std::vector<double>> rows;
  for (const auto& curve : fit.evaluations) rows.push_back(cases::stretch_fit_table_row(curve));
  io::write_csv_file(directory.path() / "stretch_fit.csv", cases::stretch_fit_table_columns(),
                     rows);
}

void run_calibrate_command(const CalibrateOptions& options) {
  const auto config = resolve_calibrate_config(options);
  auto settings = setup::calibration_settings_from(config);
  const Progress progress(options.common);
  settings.stretch_fit.on_evaluation = [&progress](const cases::StretchFitEvaluation& curve) {
    progress.update("calibrate: stretch fit, k_link " + format_significant(curve.k_link_kBT) +
                    " kBT: misfit " +
                    (curve.failure.empty() ? format_significant(curve.misfit) : "failed") + ", " +
                    format_significant(curve.wall_time_s, 3) + " s");
  };
  const auto parameters = setup::membrane_parameters_from(config);
  auto cell_mesh = setup::cell_mesh_from(config);
  setup::add_resolution_notice(cell_mesh, config);
  print_notices(cell_mesh.notices);

  // One thread whatever --threads says: the patches have 8 vertices and the cell mode is a few
  // force evaluations, so OpenMP barriers cost more than the work (on the loaded 2-core machine:
  // 0.3 s on one thread, 3 s on two, 7 s at OpenMP's default with spinning waits).
  auto common = options.common;
  common.threads = 1;
  const RunDirectory directory("calibrate", common, config);
  // Bad targets are input errors: found before the run directory exists.
  const auto calibration = cases::run_calibration(cell_mesh.mesh, parameters, settings);
  progress.done();
  directory.start(config, cell_mesh);
  directory.write_json("parameters.json", cases::fitted_parameters_document(calibration));
  if (calibration.stretch) write_stretch_fit_table(directory, calibration.stretch->curve);
  auto result = directory.result_head(true);
  result["headline"] = headline(calibration);
  result["files"] = {{"config", "config.json"}, {"parameters", "parameters.json"}};
  if (calibration.stretch) result["files"]["stretch_fit"] = "stretch_fit.csv";
  result["calibrate"] = cases::calibrate_result_section(calibration);
  directory.write_json("result.json", result);

  if (options.common.json) {
    std::cout << result.dump(2) << '\n';
  } else if (!options.common.quiet) {
    print_table(result, calibration, directory);
  }
}

void attach_calibrate(CLI::App& application) {
  auto options = std::make_shared<CalibrateOptions>();
  auto* command = application.add_subcommand(
      "calibrate",
      "Patch tests: moduli of the membrane's k parameters (hexagonal and two-triangle patches, "
      "the cell's overall bending) and the k fitted to target moduli or to the stretch curve of "
      "Mills et al. 2004, as a config file");
  command
      ->add_option(
          "--fits", options->fits,
          with_default("Fits to run, comma-separated: link_area, bend, curvature_terms, stretch "
                       "(k_link to Mills et al. 2004 under stretch.contact.*; minutes)",
                       "calibrate.fits"))
      ->type_name("LIST");
  command
      ->add_option("--target-shear-modulus", options->shear_uN_per_m,
                   with_default("Target shear modulus mu in uN/m",
                                "calibrate.target.shear_modulus_uN_per_m"))
      ->type_name("UN_PER_M");
  command
      ->add_option("--target-area-modulus", options->area_uN_per_m,
                   with_default("Target area-compression modulus K in uN/m",
                                "calibrate.target.area_modulus_uN_per_m"))
      ->type_name("UN_PER_M");
  command
      ->add_option("--target-young-modulus", options->young_uN_per_m,
                   with_default("Target 2D Young's modulus E_s in uN/m, instead of mu and K",
                                "calibrate.target.young_modulus_uN_per_m"))
      ->type_name("UN_PER_M");
  command
      ->add_option("--target-poisson-ratio", options->poisson_ratio,
                   with_default("Target 2D Poisson ratio, with --target-young-modulus",
                                "calibrate.target.poisson_ratio"))
      ->type_name("NU");
  command
      ->add_option("--target-bending-modulus", options->bending_modulus_J,
                   with_default("Target bending stiffness D of the two-triangle patch in J",
                                "calibrate.target.bending_modulus_J"))
      ->type_name("J");
  command
      ->add_option("--target-overall-bending-modulus", options->overall_bending_modulus_J,
                   with_default("Target overall bending modulus of the cell in J",
                                "calibrate.target.overall_bending_modulus_J"))
      ->type_name("J");
  add_common_options(command, options->common);
  command->callback([options] { run_calibrate_command(*options); });
}

const bool registered = register_command({"calibrate", 20, attach_calibrate});

}  // namespace
}  // namespace rbcsim::cli::calibrate_command
