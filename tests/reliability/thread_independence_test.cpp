// Results do not depend on the number of threads (DESIGN.md §6): the stretch case bit for bit with
// 1 and 2 OpenMP threads. (The coupled loop's test is tests/coupling/coupled_step_test.cpp's
// ResultsAreBitIdenticalForOneAndTwoThreads; its checkpoint resume across thread counts is in
// checkpoint_test.cpp.)
#include <gtest/gtest.h>

#include <vector>

#include "cases/stretch_case.hpp"
#include "common/thread_count_scope.hpp"
#include "membrane/membrane_model.hpp"
#include "mesh/cell_shapes.hpp"

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

}  // namespace
