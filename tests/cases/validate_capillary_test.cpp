// The paper's three-morphology comparison (§3.4, Figs. 14-18) at its resolution: the 2562-vertex
// cells, dx = 0.5 um, the 42 um capillary with its 6.8 um throat, Re = 0.04 with plasma. Long
// (minutes per cell): label `validate`, run with ctest -L validate.
// The paper's results: every cell passes; the DI peaks in the narrow section and falls back after
// it; transit time discocyte < echinocyte III < stomatocyte II.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>

#include "cases/capillary_case.hpp"
#include "config/config.hpp"
#include "setup/capillary_from_config.hpp"
#include "setup/cell_from_config.hpp"

namespace rbcsim::cases {
namespace {

CapillaryRun paper_run(const std::string& morphology) {
  const auto config = config::resolve_config(
      {.morphology = morphology, .assignments = {"capillary.geometry=paper-morphology"}});
  const auto wall = setup::capillary_wall_from(config);
  const auto settings = setup::capillary_settings_from(config, wall);
  const auto cell = setup::cell_mesh_from(config);
  return run_capillary(cell.mesh, setup::capillary_physics_from(config, wall, {}), settings);
}

TEST(ValidateCapillary, ThreeMorphologiesPassInThePapersOrder) {
  std::map<std::string, double> transit_s;
  for (const std::string morphology : {"discocyte", "echinocyte-III", "stomatocyte-II"}) {
    const auto run = paper_run(morphology);
    std::printf(
        "%s: transit %.6g s, DI initial %.4f peak %.4f at x = %.3g um (narrow %.3g-%.3g), final "
        "%.4f, Re %.4g, Ca %.4g, %zu steps\n",
        morphology.c_str(), run.transit_time_s.value_or(-1.0), run.initial_deformation_index,
        run.peak_deformation_index, run.peak_centroid_x_um, run.narrow_start_um, run.narrow_end_um,
        run.final_deformation_index, run.numbers.reynolds_number, run.numbers.capillary_number,
        run.steps);
    ASSERT_TRUE(run.ok()) << morphology << ": " << run.failure;
    EXPECT_GT(run.peak_centroid_x_um, run.narrow_start_um) << morphology;
    EXPECT_LT(run.peak_centroid_x_um, run.narrow_end_um) << morphology;
    EXPECT_LT(run.final_deformation_index, run.peak_deformation_index) << morphology;
    transit_s[morphology] = *run.transit_time_s;
  }
  EXPECT_LT(transit_s["discocyte"], transit_s["echinocyte-III"]);
  EXPECT_LT(transit_s["echinocyte-III"], transit_s["stomatocyte-II"]);
}

}  // namespace
}  // namespace rbcsim::cases
