// Results do not depend on the number of threads (docs/architecture.md), 1 and 2 OpenMP threads bit
// for bit. Every parallel code path has its test:
//   LBM sweep, both kernels, every boundary: tests/lattice/kernel_equivalence_test.cpp
//     (KernelEquivalence.OneAndTwoThreadsAreBitIdentical; populations, moments, total mass);
//   membrane forces, both kernels (1, 2, 3 threads): tests/membrane/analytic_checks_test.cpp
//     (MembraneModel.ResultDoesNotDependOnTheThreadCount);
//   IBM stencils, spreading and interpolation: tests/ibm/transfer_test.cpp
//     (KernelAndScene.ResultsDoNotDependOnTheThreadCount; spreading is deterministic by design:
//     each thread owns a node range and adds every point's share to its nodes in point order);
//   the whole coupled step in shear (walls and Lees-Edwards; positions, populations, velocity):
//     tests/coupling/coupled_step_test.cpp (CoupledStep.ResultsAreBitIdentical...);
//   checkpoint resume across thread counts: checkpoint_test.cpp;
//   shear's rates run in parallel: tests/cases/shear_case_test.cpp (ParallelRatesEqualSequential);
//   here: the quasi-static stretch, and the capillary command (fluid settling to a steady state,
//   curved walls, inlet and outlet, the coupled run and its observers) through the binary.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cases/stretch_case.hpp"
#include "common/thread_count_scope.hpp"
#include "membrane/membrane_model.hpp"
#include "mesh/cell_shapes.hpp"
#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"

namespace {

struct StretchOutcome {
  std::vector<rbcsim::cases::StretchPoint> points;
  std::vector<rbcsim::Vec3> final_positions_um;
};

StretchOutcome stretch_with(int threads) {
  const rbcsim::ThreadCountScope scope(threads);
  const auto cell = rbcsim::cases::prepare_stretch_cell(
      rbcsim::mesh::generate_cell("discocyte", 2, rbcsim::mesh::CellShapeParameters{}), {});
  const rbcsim::membrane::MembraneModel model(cell.mesh, rbcsim::membrane::MembraneParameters{});
  rbcsim::cases::StretchSettings settings;
  settings.forces_pN = {0.0, 30.0};
  StretchOutcome outcome;
  const auto run = rbcsim::cases::run_stretch(
      model, cell, settings, [&outcome](const rbcsim::cases::StretchState& state) {
        outcome.final_positions_um.assign(state.positions_um.begin(), state.positions_um.end());
      });
  EXPECT_TRUE(run.ok()) << run.failure;
  outcome.points = run.points;
  return outcome;
}

TEST(ThreadIndependence, StretchIsBitIdenticalWithOneAndTwoThreads) {
  const auto one = stretch_with(1);
  const auto two = stretch_with(2);
  ASSERT_EQ(one.points.size(), 2u);
  ASSERT_EQ(two.points.size(), 2u);
  for (std::size_t i = 0; i < one.points.size(); ++i) {
    EXPECT_EQ(one.points[i].axial_um, two.points[i].axial_um);
    EXPECT_EQ(one.points[i].transverse_um, two.points[i].transverse_um);
    EXPECT_EQ(one.points[i].iterations, two.points[i].iterations);
    EXPECT_EQ(one.points[i].residual_force_pN, two.points[i].residual_force_pN);
  }
  EXPECT_TRUE(one.final_positions_um == two.final_positions_um);
  EXPECT_GT(one.points[1].axial_um, one.points[0].axial_um + 0.1);  // it did stretch
}

// OMP_WAIT_POLICY=passive for the binaries this process starts, unless the user chose one.
struct PassiveOpenMpWaiting {
  PassiveOpenMpWaiting() : chosen(std::getenv("OMP_WAIT_POLICY") != nullptr) {
    if (!chosen) setenv("OMP_WAIT_POLICY", "passive", 1);
  }
  ~PassiveOpenMpWaiting() {
    if (!chosen) unsetenv("OMP_WAIT_POLICY");
  }
  PassiveOpenMpWaiting(const PassiveOpenMpWaiting&) = delete;
  PassiveOpenMpWaiting& operator=(const PassiveOpenMpWaiting&) = delete;
  bool chosen;
};

// The coarse capillary (dx = 1 um, the 162-vertex cell) for 33 steps: it ends upstream of the
// narrow section, a "failed" run (exit 1) with its result.json and time series all the same.
// Passive OpenMP waiting: on a loaded machine (load 8 on 2 cores) the default spinning made the
// 2-thread run 30 times slower (0.5 s -> 14-38 s); how threads wait does not change any result.
TEST(ThreadIndependence, CapillaryCommandIsBitIdenticalWithOneAndTwoThreads) {
  const rbcsim::testing::ScratchDirectory scratch;
  const PassiveOpenMpWaiting passive;
  const std::string settings =
      " --quiet --set mesh.subdivisions=2 --set mesh.method=parametric --set lattice.spacing_um=1"
      " --set capillary.throat_diameter_um=9 --set capillary.inlet_velocity_m_per_s=0.014"
      " --set capillary.fluid_tolerance=1e-5 --set capillary.max_time_s=5e-6"
      " --set capillary.sample_interval_s=6e-7";
  std::vector<nlohmann::json> sections;
  std::vector<std::string> tables;
  for (const int threads : {1, 2}) {
    const auto run_dir = scratch.path() / ("threads_" + std::to_string(threads));
    const auto run =
        rbcsim::testing::run_rbcsim("capillary --threads " + std::to_string(threads) +
                                        " --output '" + run_dir.string() + "'" + settings,
                                    scratch.path());
    EXPECT_EQ(run.exit_code, 1) << run.err;
    const auto result = rbcsim::testing::read_json(run_dir / "result.json");
    EXPECT_EQ(result["threads"], threads);
    sections.push_back(result["capillary"]);
    tables.push_back(rbcsim::testing::read_text(run_dir / "capillary_timeseries.csv"));
  }
  EXPECT_EQ(sections[0], sections[1]);
  EXPECT_EQ(tables[0], tables[1]);
  // The cell moved and deformed.
  EXPECT_NE(sections[0]["final_deformation_index"], sections[0]["initial_deformation_index"]);
}

}  // namespace
