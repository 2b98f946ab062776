// "Cell larger than the domain" (docs/architecture.md) as the pure check the experiment commands
// call before they build a simulation.
#include <gtest/gtest.h>

#include <string>

#include "common/errors.hpp"
#include "config/validation.hpp"

namespace {

using rbcsim::config::require_cell_fits_domain;

TEST(CellFitsDomain, NeedsTheKernelReachOfFluidOnEachSide) {
  // A discocyte 7.8 x 7.8 x 2.6 um, dx = 0.5 um, phi4 (reach 2): 2 um of clearance per axis.
  EXPECT_NO_THROW(require_cell_fits_domain({7.8, 7.8, 2.6}, {9.8, 20, 20}, 0.5, 2.0, "capillary"));
  try {
    require_cell_fits_domain({7.8, 7.8, 2.6}, {20, 9.7, 20}, 0.5, 2.0, "capillary.diameter_um");
    FAIL() << "accepted";
  } catch (const rbcsim::InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "capillary.diameter_um: the cell does not fit the domain along y: 7.8 um of cell "
              "plus 2 um of clearance (2 lattice spacings per side) exceed the domain's 9.7 um");
  }
  EXPECT_THROW(require_cell_fits_domain({1, 1, 30}, {50, 50, 20}, 0.25, 2.0, "shear"),
               rbcsim::InputError);
}

}  // namespace
