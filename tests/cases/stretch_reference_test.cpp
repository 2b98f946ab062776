// The comparison with measured diameters: RMS deviation, error bars, interpolation.
#include "cases/stretch_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "io/csv_table.hpp"

namespace {

namespace cases = rbcsim::cases;
using cases::StretchPoint;
using cases::StretchReferencePoint;

std::vector<StretchReferencePoint> three_measurements() {
  return {{0.0, {8.0, 7.5, 8.5}, {8.0, 7.5, 8.5}},
          {50.0, {10.0, 9.0, 11.0}, {6.0, 5.5, 6.5}},
          {100.0, {12.0, 11.0, 13.0}, {5.0, 4.0, 6.0}}};
}

StretchPoint point(double force_pN, double axial_um, double transverse_um) {
  return {.force_pN = force_pN,
          .axial_um = axial_um,
          .transverse_um = transverse_um,
          .converged = true};
}

TEST(StretchComparison, IdenticalCurveHasZeroDeviationAndEveryPointInside) {
  const std::vector<StretchPoint> simulated{point(0, 8, 8), point(50, 10, 6), point(100, 12, 5)};
  const auto comparison = cases::compare_with_reference(simulated, three_measurements());
  EXPECT_EQ(comparison.point_count, 3u);
  EXPECT_DOUBLE_EQ(*comparison.rms_axial_um, 0.0);
  EXPECT_DOUBLE_EQ(*comparison.rms_transverse_um, 0.0);
  EXPECT_EQ(comparison.inside_error_bars, 3u);
}

// Simulated at 0 and 100 pN only, along straight lines: the value at 50 pN is interpolated.
// Axial: 8.6 + 0.04 F, the reference means 8 + 0.04 F -> deviations 0.6, 0.6, 0.6; transverse
// exactly the reference.
TEST(StretchComparison, InterpolatesBetweenSimulatedForces) {
  const std::vector<StretchPoint> simulated{point(100, 12.6, 5.0), point(0, 8.6, 8.0)};
  auto reference = three_measurements();
  reference[1].transverse.mean_um = 6.5;  // on the line from 8 to 5
  const auto comparison = cases::compare_with_reference(simulated, reference);
  EXPECT_EQ(comparison.point_count, 3u);
  EXPECT_NEAR(*comparison.rms_axial_um, 0.6, 1e-12);
  EXPECT_NEAR(*comparison.rms_transverse_um, 0.0, 1e-12);
  EXPECT_EQ(comparison.axial_inside_error_bar, 2u);  // 8.6 > 8.5 at 0 pN
  EXPECT_EQ(comparison.transverse_inside_error_bar, 3u);
  EXPECT_EQ(comparison.inside_error_bars, 2u);
  // In units of the bars' upper halves 0.5, 1, 1 um: 1.2^2 + 0.6^2 + 0.6^2.
  EXPECT_NEAR(comparison.misfit, 2.16, 1e-12);
}

// A bar from 9 to 12 around 10: deviations count in the half of the bar on their side, so both
// ends have misfit 1, and a value inside has less.
TEST(StretchComparison, MisfitMeasuresDeviationsInTheHalfBarOnTheirSide) {
  const cases::MeasuredDiameter measured{10.0, 9.0, 12.0};
  EXPECT_DOUBLE_EQ(measured.misfit(9.0), 1.0);
  EXPECT_DOUBLE_EQ(measured.misfit(12.0), 1.0);
  EXPECT_DOUBLE_EQ(measured.misfit(9.5), 0.25);
  EXPECT_DOUBLE_EQ(measured.misfit(10.5), 0.0625);
  EXPECT_DOUBLE_EQ(measured.misfit(14.0), 4.0);
  EXPECT_DOUBLE_EQ(measured.misfit(10.0), 0.0);
}

TEST(StretchComparison, NeverExtrapolatesAndIgnoresUnconvergedPoints) {
  std::vector<StretchPoint> simulated{point(0, 8, 8), point(60, 11, 5.5), point(100, 99, 99)};
  simulated[2].converged = false;
  const auto comparison = cases::compare_with_reference(simulated, three_measurements());
  EXPECT_EQ(comparison.point_count, 2u);  // 0 and 50 pN; 100 pN is beyond the converged range
  EXPECT_FALSE(cases::compare_with_reference({}, three_measurements()).rms_axial_um.has_value());
}

// The shipped data: 13 forces, bars around the means.
TEST(StretchComparison, ShippedMillsDataReadsWithItsBars) {
  const auto reference = cases::stretch_reference_from(rbcsim::io::read_csv_file(
      std::string(RBCSIM_SOURCE_DIR) + "/share/reference/mills2004_stretch.csv"));
  ASSERT_EQ(reference.size(), 13u);
  EXPECT_EQ(reference.front().force_pN, 0.0);
  EXPECT_NEAR(reference.back().force_pN, 192.688, 1e-9);
  for (const auto& measured : reference) {
    EXPECT_LT(measured.axial.bar_low_um, measured.axial.mean_um);
    EXPECT_GT(measured.axial.bar_high_um, measured.axial.mean_um);
    EXPECT_TRUE(measured.transverse.contains(measured.transverse.mean_um));
  }
}

}  // namespace
