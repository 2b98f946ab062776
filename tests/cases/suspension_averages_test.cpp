// The per-morphology averages of a tube suspension (cases/suspension_case.hpp): over the same
// window as the flow's averages (the last `fraction` of the run, never the release at t = 0), each
// cell's samples counted under its own morphology.
#include <gtest/gtest.h>

#include <vector>

#include "cases/suspension_case.hpp"

namespace rbcsim::cases {
namespace {

SuspensionCellSample cell_sample(double time_s, std::size_t cell, double radial_um,
                                 double velocity_m_per_s, double deformation_index) {
  return {.time_s = time_s,
          .cell = cell,
          .centroid_um = Vec3::Zero(),
          .radial_position_um = radial_um,
          .velocity_x_m_per_s = velocity_m_per_s,
          .deformation_index = deformation_index};
}

TEST(MorphologyAverages, AverageEachKindOverTheFlowsWindowOnly) {
  // Cells 0 and 2 are kind 0, cell 1 kind 1; kind 2 has no cell. Run of 1 s, window the last half.
  const std::vector<std::size_t> kinds = {0, 1, 0};
  std::vector<SuspensionCellSample> samples;
  for (const double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const bool in_window = t >= 0.5;
    // Outside the window every figure is far off, so counting one there shows.
    samples.push_back(cell_sample(t, 0, in_window ? 1.0 : 100.0, 0.002, 0.5));
    samples.push_back(cell_sample(t, 1, in_window ? 3.0 : 100.0, 0.001, 1.5));
    samples.push_back(cell_sample(t, 2, in_window ? 2.0 : 100.0, 0.004, 0.7));
  }
  const auto averages = morphology_averages(samples, kinds, 3, 1.0, 0.5);
  ASSERT_EQ(averages.size(), 3u);
  EXPECT_EQ(averages[0].cell_samples, 6u);  // two cells, t = 0.5, 0.75, 1
  EXPECT_DOUBLE_EQ(averages[0].radial_position_um, 1.5);
  EXPECT_DOUBLE_EQ(averages[0].velocity_x_m_per_s, 0.003);
  EXPECT_DOUBLE_EQ(averages[0].deformation_index, 0.6);
  EXPECT_EQ(averages[1].cell_samples, 3u);
  EXPECT_DOUBLE_EQ(averages[1].radial_position_um, 3.0);
  EXPECT_DOUBLE_EQ(averages[1].velocity_x_m_per_s, 0.001);
  EXPECT_EQ(averages[2].cell_samples, 0u);
  EXPECT_EQ(averages[2].radial_position_um, 0.0);
  // The whole run as the window still leaves out the release.
  EXPECT_EQ(morphology_averages(samples, kinds, 3, 1.0, 1.0)[1].cell_samples, 4u);
}

}  // namespace
}  // namespace rbcsim::cases
