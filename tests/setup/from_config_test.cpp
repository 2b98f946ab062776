// The bridge from the resolved config to the engine's structs: values arrive in the right place
// and unit, per morphology, and the cell comes from the generator or the file as configured.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cases/hexagonal_patch.hpp"
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

namespace network_scaling {

// Mean edge length of a closed mesh, um (each edge is counted by both its triangles).
double mean_edge_um(const rbcsim::mesh::TriangleMesh& mesh) {
  double sum_um = 0.0;
  for (const auto& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      sum_um += (mesh.positions_um[t[i]] - mesh.positions_um[t[(i + 1) % 3]]).norm();
    }
  }
  return sum_um / (3.0 * static_cast<double>(mesh.triangles.size()));
}

// Shear and area moduli of a cell's network as the hexagonal patch at the cell's mean edge
// measures them (the paper's calibration, section 2.4), for the k the cell runs with.
rbcsim::cases::MembraneModuli cell_network_moduli(const std::string& morphology, int subdivisions,
                                                  int calibrated_triangles) {
  const auto config = resolve_config(
      {.morphology = morphology,
       .assignments = {
           "mesh.method=parametric", "mesh.subdivisions=" + std::to_string(subdivisions),
           "membrane.network_calibrated_triangle_count=" + std::to_string(calibrated_triangles)}});
  const auto cell = rbcsim::setup::cell_mesh_from(config).mesh;
  const auto parameters = rbcsim::setup::cell_membrane_parameters_from(config, cell);
  const double edge_um = mean_edge_um(cell);
  const auto stiffness = rbcsim::cases::measure_patch_stiffness(parameters, edge_um, 1e-4);
  return rbcsim::cases::network_moduli(stiffness, parameters.k_link_kBT, parameters.k_area_kBT);
}

}  // namespace network_scaling

// k_link and k_area calibrated on the 642-vertex cell (1280 triangles) give the 162-vertex cell
// of the same morphology the same shear and area moduli; applied as given (0) they give it about
// half, as the link and area terms are a stiffness per edge length.
TEST(MembraneFromConfig, CalibratedTriangleCountKeepsTheNetworkModuliOnACoarserMesh) {
  using network_scaling::cell_network_moduli;
  for (const std::string morphology : {"discocyte", "stomatocyte-II"}) {
    SCOPED_TRACE(morphology);
    const auto fine = cell_network_moduli(morphology, 3, 1280);
    const auto coarse = cell_network_moduli(morphology, 2, 1280);
    const auto as_given = cell_network_moduli(morphology, 2, 0);
    // The scale is sqrt(1280 / 320) = 2; the coarse mesh's mean edge is not exactly twice the
    // fine one's (the subdivided triangles are projected onto the curved shape), which is the
    // whole difference left: 3 %.
    EXPECT_NEAR(coarse.shear_uN_per_m / fine.shear_uN_per_m, 1.0, 0.03);
    EXPECT_NEAR(coarse.area_uN_per_m / fine.area_uN_per_m, 1.0, 0.03);
    EXPECT_NEAR(as_given.shear_uN_per_m / fine.shear_uN_per_m, 0.5, 0.03);
  }
}

TEST(MembraneFromConfig, NetworkStiffnessIsScaledOnlyWhenACalibratedCountIsSet) {
  const auto config = resolve_config({.morphology = "stomatocyte-II"});
  EXPECT_DOUBLE_EQ(rbcsim::setup::network_stiffness_scale(config, 1280), 1.0);
  const auto calibrated = config.with("membrane.network_calibrated_triangle_count", 5120);
  EXPECT_DOUBLE_EQ(rbcsim::setup::network_stiffness_scale(calibrated, 1280), 2.0);
  EXPECT_DOUBLE_EQ(rbcsim::setup::network_stiffness_scale(calibrated, 5120), 1.0);
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
