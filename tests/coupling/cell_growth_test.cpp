// Cells that grow to their size in the flow (coupling/cell_growth.hpp,
// CoupledSimulation::grow_cells): the stages rise by at most 0.1 % and end at the cell's own
// reference, bit for bit; with the volume hold the enclosed volume follows the scale's cube; and
// a run resumed in the middle of the growth is the straight run.
#include "coupling/cell_growth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "common/state_archive.hpp"
#include "coupling/coupled_simulation.hpp"
#include "coupling_fixtures.hpp"
#include "membrane/membrane_model.hpp"
#include "mesh/geometry.hpp"

namespace rbcsim::coupling {
namespace {

using testing::capsule_parameters;
using testing::periodic_fluid;
using testing::plasma_units;
using testing::sphere_mesh;

TEST(CellGrowth, StagesRiseByAtMostATenthOfAPercentAndEndAtFullSize) {
  const CellGrowth growth{0.85, 1000};
  ASSERT_EQ(growth_stage_count(growth), 150u);
  EXPECT_EQ(growth_stage_scale(growth, growth_stage(growth, 0)), 0.85);
  double previous = 0.85;
  for (std::size_t step = 1; step <= 1200; ++step) {
    const double scale = growth_stage_scale(growth, growth_stage(growth, step));
    EXPECT_GE(scale, previous) << "step " << step;
    EXPECT_LE(scale - previous, kGrowthStageScale + 1e-15) << "step " << step;
    previous = scale;
  }
  EXPECT_LT(growth_stage_scale(growth, growth_stage(growth, 999)), 1.0);
  EXPECT_EQ(growth_stage_scale(growth, growth_stage(growth, 1000)), 1.0);  // exactly
  EXPECT_DOUBLE_EQ(growth_scale(growth, 500), 0.925);
  EXPECT_EQ(growth_scale(growth, 1000), 1.0);
  EXPECT_EQ(growth_stage_count(CellGrowth{}), 0u);
  EXPECT_THROW(require_valid(CellGrowth{0.0, 10}), std::invalid_argument);
  EXPECT_THROW(require_valid(CellGrowth{1.1, 10}), std::invalid_argument);
  EXPECT_THROW(require_valid(CellGrowth{0.9, 0}), std::invalid_argument);
}

// A spherical capsule of 2 um radius (162 vertices) in a periodic box of fluid at rest, placed
// at 0.9 of its size and grown over 300 steps with the volume hold.
constexpr double kStartScale = 0.9;
constexpr std::size_t kGrowthSteps = 300;
const Vec3 kCentre(5.0, 5.0, 5.0);

struct GrowingCell {
  mesh::TriangleMesh full;
  std::unique_ptr<CoupledSimulation> simulation;
};

GrowingCell growing_cell() {
  GrowingCell setup{sphere_mesh(2, 2.0, kCentre), nullptr};
  CouplingParameters parameters;
  parameters.hold_volume = true;
  setup.simulation =
      std::make_unique<CoupledSimulation>(periodic_fluid(20, 20, 20), plasma_units(), parameters);
  setup.simulation->grow_cells({kStartScale, kGrowthSteps});
  std::vector<Vec3> start;
  for (const Vec3& p : setup.full.positions_um)
    start.push_back(kCentre + kStartScale * (p - kCentre));
  setup.simulation->add_cell(membrane::MembraneModel(setup.full, capsule_parameters(50.0)), start);
  return setup;
}

double volume_um3(const CoupledSimulation& simulation, const mesh::TriangleMesh& mesh) {
  return mesh::enclosed_volume_um3({simulation.positions_now_um(0), mesh.triangles});
}

TEST(CellGrowth, AGrownCellHoldsItsOwnReferenceAndVolume) {
  auto setup = growing_cell();
  auto& simulation = *setup.simulation;
  const membrane::MembraneModel own(setup.full, capsule_parameters(50.0));
  const double full_volume_um3 = own.reference().volume_um3;
  // At the start: the reference of the start size, and (at rest there) no force.
  EXPECT_EQ(simulation.cell_scale(), kStartScale);
  EXPECT_NEAR(simulation.cell(0).model().reference().volume_um3,
              full_volume_um3 * kStartScale * kStartScale * kStartScale, 1e-12 * full_volume_um3);
  for (const Vec3& force : simulation.cell(0).membrane_forces().total_pN) {
    EXPECT_LT(force.norm(), 1e-9);
  }
  for (std::size_t step = 0; step < kGrowthSteps / 2; ++step) simulation.step();
  // Half way the volume is at the cube of the scale reached (the hold's step error is second
  // order in a step that changes the volume by 1e-3 of itself).
  const double half_scale = growth_scale({kStartScale, kGrowthSteps}, kGrowthSteps / 2);
  EXPECT_NEAR(volume_um3(simulation, setup.full),
              full_volume_um3 * half_scale * half_scale * half_scale, 1e-4 * full_volume_um3);
  for (std::size_t step = kGrowthSteps / 2; step < kGrowthSteps; ++step) simulation.step();
  // Grown: the model's own reference again, bit for bit, and the full volume.
  EXPECT_EQ(simulation.cell_scale(), 1.0);
  EXPECT_EQ(simulation.cell(0).model().reference().edge_lengths_um,
            own.reference().edge_lengths_um);
  EXPECT_EQ(simulation.cell(0).model().reference().volume_um3, full_volume_um3);
  EXPECT_NEAR(volume_um3(simulation, setup.full), full_volume_um3, 1e-4 * full_volume_um3);
  // Afterwards the hold keeps it.
  for (int step = 0; step < 50; ++step) simulation.step();
  EXPECT_NEAR(volume_um3(simulation, setup.full), full_volume_um3, 1e-4 * full_volume_um3);
  // A sphere at its volume has its area: the membrane's own, to the mesh's departure from a
  // sphere under the link and area forces (1 %).
  const double area_um2 =
      mesh::surface_area_um2({simulation.positions_now_um(0), setup.full.triangles});
  EXPECT_NEAR(area_um2, own.reference().area_um2, 0.01 * own.reference().area_um2);
}

TEST(CellGrowth, AResumedGrowthIsTheStraightOne) {
  auto straight = growing_cell();
  for (std::size_t step = 0; step < kGrowthSteps; ++step) straight.simulation->step();

  auto first = growing_cell();
  for (std::size_t step = 0; step < kGrowthSteps / 3; ++step) first.simulation->step();
  StateArchive archive("test");
  first.simulation->save_state(archive);
  auto resumed = growing_cell();
  resumed.simulation->restore_state(archive);
  for (std::size_t step = kGrowthSteps / 3; step < kGrowthSteps; ++step) {
    resumed.simulation->step();
  }
  const auto a = straight.simulation->positions_now_um(0);
  const auto b = resumed.simulation->positions_now_um(0);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t v = 0; v < a.size(); ++v) EXPECT_EQ(a[v], b[v]) << "vertex " << v;
}

TEST(CellGrowth, IsSetBeforeTheCellsAreAdded) {
  auto setup = growing_cell();
  EXPECT_THROW(setup.simulation->grow_cells({0.9, 10}), std::invalid_argument);
}

}  // namespace
}  // namespace rbcsim::coupling
