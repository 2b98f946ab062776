// `rbcsim calibrate` end to end on a coarse cell (level 2): the run directory, result.json
// against its schema, parameters.json fed back through --config, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "io/csv_table.hpp"
#include "support/relative_difference.hpp"
#include "support/run_rbcsim.hpp"
#include "support/run_result.hpp"
#include "support/scratch_directory.hpp"

namespace {

namespace fs = std::filesystem;
using rbcsim::testing::printed_run_result;
using rbcsim::testing::read_json;
using rbcsim::testing::result_schema_problems;
using rbcsim::testing::run_rbcsim;
using rbcsim::testing::ScratchDirectory;

constexpr const char* kCoarseCell = "--set mesh.subdivisions=2 --set mesh.method=parametric ";

using rbcsim::testing::relative_difference;

TEST(CliCalibrate, WritesARunDirectoryWhoseParametersReachTheTargets) {
  const ScratchDirectory scratch;
  const auto first = scratch.path() / "first";
  const auto result = run_rbcsim(std::string("calibrate ") + kCoarseCell +
                                     "--target-shear-modulus 7.3 --target-area-modulus 20 "
                                     "--threads 1 --json --output '" +
                                     first.string() + "'",
                                 scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto printed = printed_run_result(result, first, "calibrate");
  EXPECT_EQ(read_json(first / "config.json")["run"]["command"], "calibrate");
  const auto& calibrate = printed["calibrate"];
  EXPECT_EQ(calibrate["paper"]["hexagonal"]["E_s_uN_per_m"], 29.85);
  EXPECT_LT(calibrate["hexagonal_fit"]["relative_residual"].get<double>(), 1e-3);

  // Fed back: the hexagonal patch measured with the fitted k gives the targets.
  const auto parameters = first / "parameters.json";
  const auto fitted = read_json(parameters);
  EXPECT_EQ(fitted["membrane"].size(), 5u);
  const auto second =
      run_rbcsim(std::string("calibrate ") + kCoarseCell + "--config '" + parameters.string() +
                     "' --fits bend --json --output '" + (scratch.path() / "second").string() + "'",
                 scratch.path());
  ASSERT_EQ(second.exit_code, 0) << second.err;
  const auto measured = nlohmann::json::parse(second.out)["calibrate"];
  EXPECT_LT(relative_difference(measured["hexagonal"]["mu_uN_per_m"].get<double>(), 7.3), 1e-3);
  EXPECT_LT(relative_difference(measured["hexagonal"]["K_uN_per_m"].get<double>(), 20.0), 1e-3);
  EXPECT_LT(
      relative_difference(measured["overall_bending"]["bending_modulus_J"].get<double>(), 2.5e-19),
      1e-3);
  EXPECT_FALSE(measured.contains("hexagonal_fit"));
}

// The stretch fit on the coarse cell over Mills' first four forces (a second): its table, its
// result against the schema, the curves it ran, and parameters.json, which carries the fitted
// k_link and the contact it was fitted under, so `rbcsim stretch --config` with it runs the
// fitted curve.
TEST(CliCalibrate, StretchFitWritesParametersThatRunTheFittedCurve) {
  const ScratchDirectory scratch;
  const std::string setting =
      std::string(kCoarseCell) + "--set stretch.forces_pN=0,15.987,19.338,30.754 --threads 1 ";
  const auto fit_dir = scratch.path() / "fit";
  const auto fit = run_rbcsim("calibrate --fits stretch --set stretch.contact.rigid=true " +
                                  setting + "--output '" + fit_dir.string() + "'",
                              scratch.path());
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  // The table prints the comparison with Mills as a group under the stretch fit.
  EXPECT_NE(fit.out.find("\n  comparison\n    reference"), std::string::npos) << fit.out;
  EXPECT_NE(fit.out.find("    rms_axial_um"), std::string::npos) << fit.out;
  const auto printed = read_json(fit_dir / "result.json");
  EXPECT_EQ(result_schema_problems(printed), std::vector<std::string>{});
  const auto& stretch_fit = printed["calibrate"]["stretch_fit"];
  EXPECT_EQ(stretch_fit["start_k_link_kBT"], 7.0);
  EXPECT_EQ(stretch_fit["comparison"]["point_count"], 4);
  EXPECT_EQ(printed["files"]["stretch_fit"], "stretch_fit.csv");
  const auto curves = rbcsim::io::read_csv_file(fit_dir / "stretch_fit.csv");
  EXPECT_EQ(curves.numbers("k_link_kBT").size(), stretch_fit["curves"].get<std::size_t>());
  const auto misfits = curves.numbers("misfit");
  EXPECT_EQ(*std::min_element(misfits.begin(), misfits.end()), stretch_fit["misfit"].get<double>());

  const auto parameters = read_json(fit_dir / "parameters.json");
  EXPECT_EQ(parameters["membrane"], nlohmann::json({{"k_link_kBT", stretch_fit["k_link_kBT"]}}));
  EXPECT_EQ(parameters["stretch"]["contact"]["rigid"], true);
  const auto stretch =
      run_rbcsim("stretch --config '" + (fit_dir / "parameters.json").string() + "' " + setting +
                     "--json --output '" + (scratch.path() / "stretch").string() + "'",
                 scratch.path());
  ASSERT_EQ(stretch.exit_code, 0) << stretch.err;
  // The fitted curve run again by the stretch command compares with the data as the fit said.
  EXPECT_EQ(nlohmann::json::parse(stretch.out)["stretch"]["comparison"], stretch_fit["comparison"]);
}

TEST(CliCalibrate, UnreachableTargetIsBadInputAndWritesNothing) {
  const ScratchDirectory scratch;
  const auto run_dir = scratch.path() / "run";
  const auto result = run_rbcsim(std::string("calibrate ") + kCoarseCell +
                                     "--target-shear-modulus 10 --target-area-modulus 5 "
                                     "--output '" +
                                     run_dir.string() + "'",
                                 scratch.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("calibrate.target.area_modulus_uN_per_m"), std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(run_dir));
  const auto both =
      run_rbcsim("calibrate --target-shear-modulus 10 --target-poisson-ratio 0.3", scratch.path());
  EXPECT_EQ(both.exit_code, 2);
  const auto unknown_fit = run_rbcsim("calibrate --fits bend,stiffness", scratch.path());
  EXPECT_EQ(unknown_fit.exit_code, 2);
  EXPECT_NE(unknown_fit.err.find("--fits: calibrate.fits: [1]: \"stiffness\" is not one of"),
            std::string::npos)
      << unknown_fit.err;
  const auto unloaded = run_rbcsim(
      "calibrate --fits stretch --set stretch.forces_pN=0,10 --output '" + run_dir.string() + "'",
      scratch.path());
  EXPECT_EQ(unloaded.exit_code, 2);
  EXPECT_NE(unloaded.err.find("stretch.forces_pN: the stretch fit needs forces"), std::string::npos)
      << unloaded.err;
  EXPECT_FALSE(fs::exists(run_dir));
}

}  // namespace
