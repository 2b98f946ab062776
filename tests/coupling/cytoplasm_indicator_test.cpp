// The cytoplasm's viscosity classes in the coupled loop (coupling/cytoplasm_indicator.hpp): they
// are exactly the quantised indicator of the cell at the positions of that step (update every step)
// or of an earlier step whose positions are within the update displacement, also as the cell drifts
// across a periodic face; without a contrast there are none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <span>
#include <vector>

#include "common/state_archive.hpp"
#include "coupling/coupling_fixtures.hpp"
#include "coupling/cytoplasm_indicator.hpp"
#include "ibm/inside_indicator.hpp"
#include "mesh/geometry.hpp"

namespace rbcsim::coupling {
namespace {

using testing::plasma_units;
using testing::sphere_mesh;

// A sphere of radius 5 dx whose box reaches across the face x = 0, carried along +x (and a
// little along y) by a uniform flow of the periodic box.
std::unique_ptr<CoupledSimulation> drifting_sphere(double viscosity_ratio,
                                                   double update_displacement_lu,
                                                   double flow_lu = 0.04) {
  lattice::FluidParameters parameters;
  parameters.inner_viscosity_ratio = viscosity_ratio;
  auto fluid = std::make_unique<lattice::FluidSolver>(lattice::LatticeGrid(24, 20, 20), parameters);
  fluid->initialise_equilibrium(1.0, {flow_lu, 0.25 * flow_lu, 0.0});
  CouplingParameters coupling;
  coupling.cytoplasm_update_lu = update_displacement_lu;
  auto simulation = std::make_unique<CoupledSimulation>(std::move(fluid), plasma_units(), coupling);
  const auto sphere = sphere_mesh(3, 2.5, Vec3(0.9, 4.6, 4.8));  // um; dx = 0.5 um
  simulation->add_cell(membrane::MembraneModel(sphere, testing::capsule_parameters(100.0)),
                       sphere.positions_um);
  return simulation;
}

// The classes of the cell at `positions`: its indicator quantised, zero elsewhere.
std::vector<lattice::ViscosityClass> expected_classes(const CoupledSimulation& simulation,
                                                      std::span<const Vec3> positions) {
  const Cell& cell = simulation.cell(0);
  ibm::SurfaceIndicator indicator;
  indicator.compute(positions, cell.model().triangles(), 1.0);  // phi2
  std::vector<lattice::ViscosityClass> classes(simulation.fluid().grid().node_count(), 0);
  const ibm::NodeBox& box = indicator.box();
  std::size_t n = 0;
  for (int k = 0; k < box.count[2]; ++k) {
    for (int j = 0; j < box.count[1]; ++j) {
      for (int i = 0; i < box.count[0]; ++i, ++n) {
        std::size_t node = 0;
        if (ibm::grid_node_of(simulation.grid_view(), box, i, j, k, node)) {
          classes[node] = lattice::viscosity_class(indicator.values()[n]);
        }
      }
    }
  }
  return classes;
}

TEST(CytoplasmIndicator, ClassesFollowTheCellEveryStepAcrossAPeriodicFace) {
  auto simulation = drifting_sphere(5.0, 0.0);
  const double start_x = simulation->cell(0).centroid_lu().x();
  const double volume_lu = mesh::enclosed_volume_um3(sphere_mesh(3, 5.0, Vec3::Zero()));
  for (int step = 1; step <= 60; ++step) {
    simulation->step();
    if (step % 10 != 0 && step != 1) continue;
    const auto classes = simulation->fluid().viscosity_classes();
    // Where the cell was when the step began.
    const auto expected =
        expected_classes(*simulation, simulation->cell(0).previous_positions_lu());
    ASSERT_TRUE(std::equal(classes.begin(), classes.end(), expected.begin())) << "step " << step;
    double sum = 0.0;
    for (const auto node_class : classes) sum += node_class / 255.0;
    // The smoothing's curvature bias, 0.39 (eps / R)^2 = 1.6 %, plus the cell's deformation.
    EXPECT_NEAR(sum / volume_lu, 1.016, 0.01) << "step " << step;
  }
  // It moved by more than a spacing, through x = 0: stale classes would have been caught.
  EXPECT_GT(simulation->cell(0).centroid_lu().x() - start_x, 1.5);
  EXPECT_GT(simulation->phase_times().indicator_s, 0.0);
}

// With the default cadence the classes are those of the positions at some earlier step, no
// vertex having moved 0.05 dx since, and they are recomputed far less often than every step.
TEST(CytoplasmIndicator, ClassesLagTheCellByLessThanTheUpdateDisplacement) {
  const double limit = CouplingParameters{}.cytoplasm_update_lu;
  auto simulation = drifting_sphere(5.0, limit, 0.01);  // 0.01 dx per step
  // The positions at the start of every step.
  std::vector<std::vector<Vec3>> starts;
  std::size_t last_match = 0;
  int recomputations = 0;
  for (int step = 0; step < 60; ++step) {
    const auto now = simulation->cell(0).positions_lu();
    starts.emplace_back(now.begin(), now.end());
    simulation->step();
    const auto classes = simulation->fluid().viscosity_classes();
    // The latest start whose classes these are.
    std::size_t match = starts.size();
    for (std::size_t m = starts.size(); m-- > last_match;) {
      const auto expected = expected_classes(*simulation, starts[m]);
      if (std::equal(classes.begin(), classes.end(), expected.begin())) {
        match = m;
        break;
      }
    }
    ASSERT_LT(match, starts.size()) << "step " << step << ": classes of no earlier position";
    double largest = 0.0;
    for (std::size_t v = 0; v < starts.back().size(); ++v) {
      largest = std::max(largest, (starts.back()[v] - starts[match][v]).norm());
    }
    EXPECT_LT(largest, limit) << "step " << step;
    if (match != last_match || step == 0) ++recomputations;
    last_match = match;
  }
  std::printf("60 steps, %d recomputations of the indicator\n", recomputations);
  EXPECT_LT(recomputations, 20);
  EXPECT_GT(recomputations, 5);
}

// An update writes the classes when it recomputes them, and also when a restored indicator
// rebuilds them from the checkpoint's positions with no recomputation due: a caller that copies
// the classes elsewhere when they are written (the slabs of the distributed lattice) must hear
// of both.
TEST(CytoplasmIndicator, UpdateReportsTheClassesRebuiltAfterARestore) {
  auto simulation = drifting_sphere(5.0, CouplingParameters{}.cytoplasm_update_lu, 0.0);
  const auto cells = simulation->cells();
  const ibm::GridView grid = simulation->grid_view();
  std::vector<lattice::ViscosityClass> classes(simulation->fluid().grid().node_count(), 0);
  CytoplasmIndicator indicator(1.0, CouplingParameters{}.cytoplasm_update_lu);
  EXPECT_TRUE(indicator.update(cells, grid, classes));   // the first: computed
  EXPECT_FALSE(indicator.update(cells, grid, classes));  // nothing moved: not due
  StateArchive archive("test");
  indicator.save_state(archive);
  CytoplasmIndicator restored(1.0, CouplingParameters{}.cytoplasm_update_lu);
  restored.restore_state(archive, cells);
  std::vector<lattice::ViscosityClass> rebuilt(classes.size(), 0);
  EXPECT_TRUE(restored.update(cells, grid, rebuilt));  // not due, but rebuilt
  EXPECT_EQ(rebuilt, classes);
  EXPECT_FALSE(restored.update(cells, grid, rebuilt));
}

TEST(CytoplasmIndicator, NoContrastNoClasses) {
  auto simulation = drifting_sphere(1.0, 0.0);
  simulation->step();
  EXPECT_FALSE(simulation->fluid().has_viscosity_contrast());
  EXPECT_EQ(simulation->phase_times().indicator_s, 0.0);
}

}  // namespace
}  // namespace rbcsim::coupling
