#include "lattice/benchmark.hpp"

#include <omp.h>

#include <gtest/gtest.h>

namespace rbcsim::lattice {
namespace {

// Speed is measured, never asserted: this only checks that the measurement runs and restores the
// caller's thread count.
TEST(FluidBenchmark, ReportsPositiveThroughputAndRestoresThreads) {
  const int threads_before = omp_get_max_threads();
  const auto throughput = measure_fluid_mlups(8, 8, 4, 4, 1);
  EXPECT_GT(throughput.optimised_mlups, 0.0);
  EXPECT_GT(throughput.reference_mlups, 0.0);
  EXPECT_GT(throughput.single_mlups, 0.0);
  EXPECT_EQ(omp_get_max_threads(), threads_before);
}

}  // namespace
}  // namespace rbcsim::lattice
