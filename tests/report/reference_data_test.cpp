// The Mills et al. (2004) stretch data the report plots, as embedded in the binary.
#include <gtest/gtest.h>

#include <cmath>

#include <algorithm>

#include "report/reference_data.hpp"

namespace {

// The embedded Mills et al. (2004) data: 13 forces from 0 to about 193 pN, the cell stretching
// along the pull and narrowing across it, every error bar positive.
TEST(Mills2004Reference, IsEmbeddedWithItsErrorBars) {
  const auto& mills = rbcsim::report::mills2004_stretch();
  ASSERT_EQ(mills.force_pN.size(), 13u);
  EXPECT_EQ(mills.force_pN.front(), 0.0);
  EXPECT_NEAR(mills.force_pN.back(), 193, 1);
  for (const auto* column :
       {&mills.axial_um, &mills.axial_error_um, &mills.transverse_um, &mills.transverse_error_um}) {
    EXPECT_EQ(column->size(), 13u);
  }
  EXPECT_TRUE(std::is_sorted(mills.force_pN.begin(), mills.force_pN.end()));
  EXPECT_GT(mills.axial_um.back(), mills.axial_um.front());
  EXPECT_LT(mills.transverse_um.back(), mills.transverse_um.front());
  for (std::size_t i = 0; i < 13; ++i) {
    EXPECT_GT(mills.axial_error_um[i], 0) << i;
    EXPECT_GT(mills.transverse_error_um[i], 0) << i;
  }
}

}  // namespace

namespace {

using rbcsim::report::pries1990_tube_to_discharge_hematocrit;
using rbcsim::report::pries1992_relative_apparent_viscosity;

// The fits as coded here against the table share/reference computed from them in another
// language (Python, 6 significant digits): a mistyped constant shows in some row.
TEST(PriesTubeFlow, FitsReproduceTheTableComputedFromThemElsewhere) {
  const auto& rows = rbcsim::report::pries_tube_flow_table();
  ASSERT_EQ(rows.size(), 18u);  // D 5-100 um at H_D 0.30 and 0.45
  for (const auto& row : rows) {
    EXPECT_NEAR(pries1992_relative_apparent_viscosity(row.diameter_um, row.discharge_hematocrit),
                row.relative_apparent_viscosity, 1e-5 * row.relative_apparent_viscosity)
        << row.diameter_um << " um, H_D " << row.discharge_hematocrit;
    EXPECT_NEAR(pries1990_tube_to_discharge_hematocrit(row.diameter_um, row.discharge_hematocrit),
                row.tube_to_discharge_hematocrit, 1e-5 * row.tube_to_discharge_hematocrit)
        << row.diameter_um << " um, H_D " << row.discharge_hematocrit;
  }
}

// What the fits are for: plasma alone has viscosity 1; the apparent viscosity at H_D 0.45 falls
// from 5 um to a minimum near 7-8 um and rises again (Fahraeus-Lindqvist); H_T < H_D in narrow
// tubes, approaching H_D in wide ones (Fahraeus).
TEST(PriesTubeFlow, FitsShowTheFahraeusAndFahraeusLindqvistEffects) {
  for (const double diameter_um : {5.0, 10.0, 40.0, 200.0}) {
    EXPECT_NEAR(pries1992_relative_apparent_viscosity(diameter_um, 0.0), 1.0, 1e-12);
  }
  const auto at_045 = [](double d) { return pries1992_relative_apparent_viscosity(d, 0.45); };
  EXPECT_LT(at_045(7.5), at_045(5.0));
  EXPECT_LT(at_045(7.5), at_045(10.0));
  EXPECT_LT(at_045(10.0), at_045(20.0));
  EXPECT_LT(at_045(20.0), at_045(40.0));
  EXPECT_LT(pries1992_relative_apparent_viscosity(20.0, 0.30), at_045(20.0));
  for (const double diameter_um : {10.0, 20.0, 40.0}) {
    EXPECT_LT(pries1990_tube_to_discharge_hematocrit(diameter_um, 0.45), 0.9) << diameter_um;
  }
  EXPECT_NEAR(pries1990_tube_to_discharge_hematocrit(2000.0, 0.45), 1.0, 1e-3);
}

// The wide-tube limit, written out by hand: 1 + 2.2 ((1 - H)^-0.8 - 1) / (0.55^-0.8 - 1); 3.2 at
// H 0.45 by construction, 1 without cells, and a 2000 um tube (the widest of Pries' data) within
// 1e-3 of it (its mu_0.45 is 3.2 - 2.44 exp(-0.06 x 2000^0.645) = 3.1992).
TEST(TubeFlowReference, TheWideTubeLimitIsTheBulkFit) {
  using rbcsim::report::pries1992_large_tube_relative_viscosity;
  for (const double h : {0.0, 0.1, 0.3, 0.45}) {
    const double by_hand =
        1.0 + 2.2 * (std::pow(1.0 - h, -0.8) - 1.0) / (std::pow(0.55, -0.8) - 1.0);
    EXPECT_NEAR(pries1992_large_tube_relative_viscosity(h), by_hand, 1e-12) << h;
    EXPECT_NEAR(pries1992_relative_apparent_viscosity(2000.0, h), by_hand, 1e-3) << h;
  }
  EXPECT_NEAR(pries1992_large_tube_relative_viscosity(0.45), 3.2, 1e-12);
}

// The cell-free-layer rows with their status: three in-vivo values read in a source, two
// simulation values of a 20 um tube recalled from a figure.
TEST(CellFreeLayerReference, KeepsEachRowsStatus) {
  const auto& rows = rbcsim::report::cell_free_layer_reference();
  ASSERT_EQ(rows.size(), 5u);
  int recalled_tube_rows = 0;
  for (const auto& row : rows) {
    EXPECT_GT(row.cell_free_layer_um, 0.0);
    EXPECT_GT(row.uncertainty_um, 0.0);
    EXPECT_TRUE(row.status == "READ_TEXT" || row.status == "RECALLED") << row.status;
    if (row.status == "RECALLED" && row.hematocrit_kind == "tube" && row.diameter_um == 20.0) {
      ++recalled_tube_rows;
    }
  }
  EXPECT_EQ(recalled_tube_rows, 2);
}

}  // namespace
