// Shapes from membrane mechanics at low resolution: the skeleton's reference spheroid, a
// minimisation that holds area and volume and reaches its force tolerance, the discocyte's
// profile against Evans & Fung (1972) - an independent measurement the model is not fitted to -,
// the morphology measures on the drawn shapes, and the failures (bad settings exit 2, a
// minimisation out of iterations exit 1).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "common/errors.hpp"
#include "mesh/cell_shapes.hpp"
#include "mesh/geometry.hpp"
#include "mesh/inspection.hpp"
#include "mesh/stl_writer.hpp"
#include "shapes/energy_shape.hpp"
#include "shapes/named_cells.hpp"
#include "shapes/sequence.hpp"
#include "shapes/shape_analysis.hpp"
#include "shapes/shipped_shapes.hpp"

namespace {

namespace shapes = rbcsim::shapes;
namespace mesh = rbcsim::mesh;

double reduced_volume_of(const mesh::TriangleMesh& m) {
  return mesh::reduced_volume(mesh::surface_area_um2(m), mesh::enclosed_volume_um3(m));
}

TEST(EnergyShape, SkeletonReferenceIsAnOblateSpheroidOfTheRequestedSize) {
  const auto spheroid = shapes::oblate_spheroid(3, 0.96, 134.09);
  EXPECT_NEAR(mesh::surface_area_um2(spheroid), 134.09, 1e-9);
  EXPECT_NEAR(reduced_volume_of(spheroid), 0.96, 1e-9);
  const auto report = mesh::inspect_mesh(spheroid);
  EXPECT_LT(report.principal_extents_um.z(), report.principal_extents_um.x());  // oblate
  EXPECT_THROW(shapes::oblate_spheroid(3, 0.9999, 134.09), rbcsim::InputError);
}

TEST(EnergyShape, MinimisationHoldsAreaAndVolumeAndConverges) {
  shapes::EnergyShapeSettings settings;  // the discocyte's Delta a0, at 162 vertices
  const auto shape = shapes::minimise_shape(2, settings);
  ASSERT_EQ(shape.trials.size(), 2u);  // one per path
  for (const auto& trial : shape.trials) {
    EXPECT_TRUE(trial.valid());
    EXPECT_LT(trial.max_force_pN, settings.force_tolerance_pN);
  }
  // Held to 1e-10 relative, then rounded to single precision (relative 6e-8 per coordinate).
  EXPECT_NEAR(mesh::surface_area_um2(shape.mesh), settings.area_um2, 1e-5 * settings.area_um2);
  EXPECT_NEAR(reduced_volume_of(shape.mesh), settings.reduced_volume, 1e-5);
  EXPECT_EQ(mesh::inspect_mesh(shape.mesh).sliver_triangle_count, 0u);
  EXPECT_EQ(mesh::inspect_mesh(shape.mesh).genus, 0);
}

TEST(EnergyShape, SeededTrialsAreReproducibleAndTheLowestWins) {
  shapes::EnergyShapeSettings settings;
  settings.trials = 2;
  const auto first = shapes::minimise_shape(2, settings);
  const auto again = shapes::minimise_shape(2, settings);
  EXPECT_EQ(first.mesh.positions_um, again.mesh.positions_um);
  ASSERT_EQ(first.trials.size(), 4u);  // two per path
  const auto& best = first.trials[first.best_trial];
  for (const auto& trial : first.trials) {
    EXPECT_LE(best.energies.total_pN_um(), trial.energies.total_pN_um());
  }
  EXPECT_NE(first.trials[0].seed, first.trials[1].seed);
  EXPECT_EQ(first.trials[0].path, "soft");
  EXPECT_EQ(first.trials[2].path, "stiff");
}

// The continuation path deflates at the discocyte's Delta a0 and then walks it to the shape's: at
// a shape whose Delta a0 is the start it is the stiff path, stage for stage, and its two settings
// appear in the settings record only when a path uses them (the shipped meshes' records were
// written without them, and a run finds a shipped mesh by its record).
TEST(EnergyShape, TheContinuationPathIsTheStiffPathWhenThereIsNothingToWalk) {
  shapes::EnergyShapeSettings settings;  // Delta a0 = 1, the continuation's start
  settings.paths = {"stiff"};
  const auto stiff = shapes::minimise_shape(2, settings);
  EXPECT_FALSE(shapes::to_json(settings).contains("continuation_step"));
  settings.paths = {"continuation"};
  const auto continued = shapes::minimise_shape(2, settings);
  EXPECT_TRUE(shapes::to_json(settings).contains("continuation_step"));
  EXPECT_EQ(continued.mesh.positions_um, stiff.mesh.positions_um);
  EXPECT_EQ(continued.trials.front().iterations, stiff.trials.front().iterations);
}

// The continuation walks Delta a0 from the discocyte's to the shape's in equal steps no longer
// than continuation_step, at the target volume and with the full skeleton, and reaches a minimum
// of the shape's model: converged, the volume held, its realised area difference above the
// discocyte's.
TEST(EnergyShape, TheContinuationPathWalksDeltaA0ToTheShapes) {
  shapes::EnergyShapeSettings settings;
  settings.relaxed_area_difference = 3.0;
  settings.continuation_step = 0.5;
  const auto& path = shapes::energy_paths().find("continuation", "test");
  const auto stages = shapes::energy_stages(path, settings, 100.0);
  ASSERT_EQ(stages.size(), static_cast<std::size_t>(settings.volume_stages) + 4);
  for (int k = 0; k < settings.volume_stages; ++k) {
    EXPECT_EQ(stages[static_cast<std::size_t>(k)].relaxed_area_difference, 1.0);
  }
  const std::vector<double> walk = {1.5, 2.0, 2.5, 3.0};
  for (std::size_t k = 0; k < walk.size(); ++k) {
    const auto& stage = stages[static_cast<std::size_t>(settings.volume_stages) + k];
    EXPECT_DOUBLE_EQ(stage.relaxed_area_difference, walk[k]);
    EXPECT_EQ(stage.volume_um3, stages.back().volume_um3);
    EXPECT_EQ(stage.skeleton_fraction, 1.0);
  }
  EXPECT_EQ(stages.back().iterations, settings.max_iterations);

  settings.paths = {"continuation"};
  const auto shape = shapes::minimise_shape(2, settings);
  ASSERT_TRUE(shape.trials.front().valid());
  EXPECT_NEAR(reduced_volume_of(shape.minimum), settings.reduced_volume, 1e-5);
  settings.relaxed_area_difference = 1.0;
  const auto disc = shapes::minimise_shape(2, settings);
  EXPECT_GT(shape.reduced_area_difference, disc.reduced_area_difference);
}

TEST(EnergyShape, TheDiscocyteIsEvansAndFungsWithinAQuarterOfAnEdge) {
  // The minimum at the discocyte's Delta a0 and Lim's moduli, 642 vertices: nothing of Evans &
  // Fung's shape enters the model, yet its profile lies within 0.15 um of theirs (the issue's
  // bound, 0.3 of this mesh's 0.5 um edge).
  shapes::EnergyShapeSettings settings;
  settings.relaxed_area_difference =
      shapes::shape_sequence().find("discocyte", "test").relaxed_area_difference;
  const auto shape = shapes::minimise_shape(3, settings);
  const auto distance = shapes::distance_from_evans_fung(shape.mesh);
  EXPECT_LT(distance.max_um, 0.15);
  EXPECT_TRUE(shapes::find_spicules(shape.mesh).tip_vertices.empty());
}

TEST(ShapeAnalysis, CountsTheDrawnEchinocytesSpiculesAndMeasuresTheDrawnCup) {
  // The parametric shapes have known features: 36 spicules on a Fibonacci spiral, and a cup
  // whose cavity is more than 40 % of the cell's height (mesh/stomatocyte.hpp).
  const auto echinocyte = mesh::generate_cell("echinocyte-III", 4);
  const auto spicules = shapes::find_spicules(echinocyte);
  EXPECT_EQ(spicules.tip_vertices.size(), 36u);
  EXPECT_LT(spicules.nearest_spacing_cv, 0.15);  // spread evenly by repulsion
  EXPECT_TRUE(shapes::find_spicules(mesh::generate_cell("discocyte", 4)).tip_vertices.empty());
  const auto cup = shapes::measure_invagination(mesh::generate_cell("stomatocyte-II", 4));
  EXPECT_GT(cup.depth_to_diameter, 0.3);
  EXPECT_GT(cup.cup_offset_um, 0.5);
  const auto disc = shapes::measure_invagination(mesh::generate_cell("discocyte", 4));
  EXPECT_LT(disc.cup_offset_um, 0.05);
  // Evans-Fung's dimple: (2.57 - 0.81) / 2 um deep in a 7.82 um disc.
  EXPECT_NEAR(disc.depth_um, 0.88, 0.03);
  EXPECT_NEAR(shapes::distance_from_evans_fung(mesh::generate_cell("discocyte", 4)).max_um, 0.0,
              0.01);
}

TEST(EnergyShape, SettingsTheModelCannotTakeAreInputErrors) {
  shapes::EnergyShapeSettings settings;
  settings.reduced_volume = 0.97;  // above the reference's 0.96: nothing to deflate from
  try {
    shapes::minimise_shape(2, settings);
    FAIL() << "expected an InputError";
  } catch (const rbcsim::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("mesh.energy.reduced_volume"), std::string::npos);
  }
  settings = {};
  settings.bending_modulus_J = 0.0;
  EXPECT_THROW(shapes::minimise_shape(2, settings), rbcsim::InputError);
}

TEST(EnergyShape, AMinimisationOutOfIterationsIsARuntimeFailureNamingTheResidual) {
  shapes::EnergyShapeSettings settings;
  settings.max_iterations = 3;
  settings.stage_iterations = 3;
  settings.paths = {"stiff"};
  try {
    shapes::minimise_shape(2, settings);
    FAIL() << "expected a RuntimeFailure";
  } catch (const rbcsim::RuntimeFailure& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("did not converge"), std::string::npos) << message;
    EXPECT_NE(message.find("mesh.energy.force_tolerance_pN"), std::string::npos) << message;
  }
}

TEST(NamedCells, MethodsAndShapesComeFromTheirRegistries) {
  shapes::NamedCellSettings settings;
  settings.subdivisions = 2;
  settings.method = "parametric";
  EXPECT_EQ(shapes::make_named_cell("discocyte", "--shape", settings).mesh.vertex_count(), 162u);
  try {
    shapes::make_named_cell("stomatocyte-I", "--shape", settings);
    FAIL() << "the parametric generators have no stomatocyte I";
  } catch (const rbcsim::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("--shape"), std::string::npos);
  }
  settings.method = "annealed";
  EXPECT_THROW(shapes::make_named_cell("discocyte", "--shape", settings), rbcsim::InputError);
}

TEST(ShippedShapes, TheIcosphereStlReaderRoundTripsAGeneratedShape) {
  shapes::EnergyShapeSettings settings;
  const auto shape = shapes::minimise_shape(2, settings);
  std::ostringstream stl;
  mesh::write_stl_binary(stl, shape.mesh);
  const auto read = shapes::read_icosphere_stl(stl.str(), 2);
  EXPECT_EQ(read.triangles, shape.mesh.triangles);
  EXPECT_EQ(read.positions_um, shape.mesh.positions_um);  // single precision both ways
  EXPECT_THROW(shapes::read_icosphere_stl(stl.str(), 3), std::runtime_error);
}

}  // namespace
