// The benchmark helper runs and leaves the OpenMP set-up as it found it. Speed is measured by
// `rbcsim bench`, never asserted here.
#include "ibm/benchmark.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <stdexcept>

namespace {

using rbcsim::ibm::find_delta_kernel;
using rbcsim::ibm::measure_ibm_step_us;

TEST(IbmBenchmark, MeasuresAPositiveTimeAndRestoresTheThreadCount) {
  const int threads_before = omp_get_max_threads();
  const double step_us =
      measure_ibm_step_us(200, {12, 12, 8, true, true, false}, find_delta_kernel("phi4"), 1);
  EXPECT_TRUE(std::isfinite(step_us));
  EXPECT_GT(step_us, 0.0);
  EXPECT_EQ(omp_get_max_threads(), threads_before);
}

TEST(IbmBenchmark, RejectsFewerThanOneThread) {
  EXPECT_THROW(measure_ibm_step_us(10, {4, 4, 4, true, true, true}, find_delta_kernel("phi2"), 0),
               std::invalid_argument);
}

}  // namespace
