// The bridge from the resolved config to the engine's structs: values arrive in the right place
// and unit, per morphology, and the cell comes from the generator or the file as configured.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "config/config.hpp"
#include "mesh/echinocyte.hpp"
#include "setup/cell_from_config.hpp"
#include "setup/membrane_from_config.hpp"

namespace {

using rbcsim::config::ConfigRequest;
using rbcsim::config::resolve_config;

TEST(MembraneFromConfig, DiscocyteDefaultsAreTableTwoInPiconewtonMicrometres) {
  const auto parameters = rbcsim::setup::membrane_parameters_from(resolve_config());
  // Table 2 of the paper, discocyte column.
  EXPECT_DOUBLE_EQ(parameters.k_link_kBT, 7.0);
  EXPECT_DOUBLE_EQ(parameters.k_bend_kBT, 50.0);
  EXPECT_DOUBLE_EQ(parameters.k_area_kBT, 5.0);
  EXPECT_DOUBLE_EQ(parameters.k_volume_kBT, 20.0);
  EXPECT_DOUBLE_EQ(parameters.k_area_difference_kBT, 300.0);
  EXPECT_DOUBLE_EQ(parameters.k_total_curvature_kBT, 100.0);
  EXPECT_DOUBLE_EQ(parameters.tau_bend_rad, std::numbers::pi / 6);
  EXPECT_DOUBLE_EQ(parameters.tau_total_curvature, 3.87);
  // kBT = 4.100531391e-21 J = 4.100531391e-3 pN um.
  EXPECT_NEAR(parameters.thermal_energy_pN_um, 4.100531391e-3, 1e-15);
  EXPECT_EQ(parameters.forces.size(), 6u);
}

TEST(MembraneFromConfig, MorphologyAndOverridesReachTheStruct) {
  const auto stomatocyte = rbcsim::setup::membrane_parameters_from(resolve_config(
      {.morphology = "stomatocyte-II",
       .assignments = {"membrane.forces=link,bend,area,volume", "membrane.distribution=paper",
                       "membrane.viscosity_solve_tolerance=3e-5"}}));
  // Table 2, stomatocyte II column.
  EXPECT_DOUBLE_EQ(stomatocyte.k_link_kBT, 11.0);
  EXPECT_DOUBLE_EQ(stomatocyte.k_bend_kBT, 80.0);
  EXPECT_DOUBLE_EQ(stomatocyte.k_area_difference_kBT, 660.0);
  EXPECT_DOUBLE_EQ(stomatocyte.k_total_curvature_kBT, 220.0);
  EXPECT_EQ(stomatocyte.forces, (std::vector<std::string>{"link", "bend", "area", "volume"}));
  EXPECT_EQ(stomatocyte.distribution, "paper");
  EXPECT_DOUBLE_EQ(stomatocyte.viscosity_solve_tolerance, 3e-5);
}

TEST(CellFromConfig, GeneratesTheMorphologyAtTheConfiguredLevel) {
  const auto cell = rbcsim::setup::cell_mesh_from(
      resolve_config({.morphology = "stomatocyte-II", .assignments = {"mesh.subdivisions=3"}}));
  EXPECT_EQ(cell.mesh.vertex_count(), 642u);  // 10 * 4^3 + 2
  EXPECT_EQ(cell.source, "built-in stomatocyte-II level 3");
}

TEST(CellFromConfig, EchinocyteSpiculeCountReachesTheGenerator) {
  const int spicules = 44;
  const auto cell = rbcsim::setup::cell_mesh_from(
      resolve_config({.morphology = "echinocyte-III",
                      .assignments = {"mesh.method=parametric", "mesh.echinocyte.spicule_count=" +
                                                                    std::to_string(spicules)}}));
  std::vector<double> radii;
  for (const auto& p : cell.mesh.positions_um) radii.push_back(p.norm());
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  const double median_radius_um = radii[radii.size() / 2];
  // Along every one of the 44 spicule axes there is a vertex well above the body: a tip.
  for (const auto& axis : rbcsim::mesh::spicule_axes(spicules)) {
    double highest_along_axis_um = 0.0;
    for (const auto& p : cell.mesh.positions_um) {
      if (p.normalized().dot(axis) > std::cos(10.0 * std::numbers::pi / 180.0)) {
        highest_along_axis_um = std::max(highest_along_axis_um, p.norm());
      }
    }
    EXPECT_GT(highest_along_axis_um, median_radius_um + 0.4);
  }
}

// mesh::resolution_notice reaches the run: told when it starts and kept in config.json. A mesh
// file is the user's own and is not compared with anything.
TEST(CellFromConfig, AGeneratedShapeTheMeshDoesNotResolveGetsARunNotice) {
  const auto config =
      resolve_config({.morphology = "echinocyte-III",
                      .assignments = {"mesh.subdivisions=3", "mesh.method=parametric"}});
  auto coarse = rbcsim::setup::cell_mesh_from(config);
  EXPECT_TRUE(coarse.run_notices.empty());
  rbcsim::setup::add_resolution_notice(coarse, config);
  ASSERT_EQ(coarse.run_notices.size(), 1u);
  EXPECT_NE(coarse.run_notices[0].find("echinocyte-III at mesh.subdivisions = 3"),
            std::string::npos)
      << coarse.run_notices[0];

  const std::string file = RBCSIM_SOURCE_DIR "/meshes/echinocyte-III_n3.stl";
  const auto from_file =
      resolve_config({.morphology = "echinocyte-III",
                      .assignments = {"mesh.subdivisions=3", "mesh.file=" + file}});
  auto imported = rbcsim::setup::cell_mesh_from(from_file);
  rbcsim::setup::add_resolution_notice(imported, from_file);
  EXPECT_TRUE(imported.run_notices.empty());
}

TEST(CellFromConfig, ReadsTheConfiguredMeshFile) {
  const std::string file = RBCSIM_SOURCE_DIR "/meshes/discocyte_n3.stl";
  const auto cell =
      rbcsim::setup::cell_mesh_from(resolve_config({.assignments = {"mesh.file=" + file}}));
  EXPECT_EQ(cell.mesh.vertex_count(), 642u);
  EXPECT_EQ(cell.source, file);
}

// The paper's 2562-vertex cell (edges ~0.25 um) on dx = 0.5 um gets the notice; on dx = 0.25 um,
// or the 642-vertex cell (edges ~0.5 um) on dx = 0.5 um, does not.
TEST(CellFromConfig, EdgesUnderThreeQuartersOfASpacingGetANotice) {
  // The parametric (Evans-Fung) cell, whose mean edge the figure below is.
  auto paper_cell =
      rbcsim::setup::cell_mesh_from(resolve_config({.assignments = {"mesh.method=parametric"}}));
  rbcsim::setup::add_edge_spacing_notice(paper_cell, 0.25);
  EXPECT_TRUE(paper_cell.run_notices.empty());
  rbcsim::setup::add_edge_spacing_notice(paper_cell, 0.5);
  ASSERT_EQ(paper_cell.run_notices.size(), 1u);
  EXPECT_NE(paper_cell.run_notices[0].find("0.49 lattice spacings (lattice.spacing_um = 0.5)"),
            std::string::npos)
      << paper_cell.run_notices[0];

  auto coarse_cell = rbcsim::setup::cell_mesh_from(
      resolve_config({.assignments = {"mesh.subdivisions=3", "mesh.method=parametric"}}));
  rbcsim::setup::add_edge_spacing_notice(coarse_cell, 0.5);
  EXPECT_TRUE(coarse_cell.run_notices.empty());
}

}  // namespace
