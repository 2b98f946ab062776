// The Mills et al. (2004) stretch data the report plots, as embedded in the binary.
#include <gtest/gtest.h>

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
