// The kernels' defining properties (Peskin 2002, §6): partition of unity and vanishing first
// moment for every offset, compact support, and the extra moment conditions of phi3 and phi4.
#include "ibm/delta_kernels.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ibm/expect_input_error.hpp"

namespace {

using rbcsim::ibm::DeltaKernel;
using rbcsim::ibm::find_delta_kernel;

// Offsets r in [0, 1) of a point from the node below it, including the special ones (on a node,
// midway) and irrational-looking ones.
std::vector<double> sample_offsets() {
  std::vector<double> offsets;
  for (int step = 0; step < 64; ++step) offsets.push_back(step / 64.0);
  offsets.push_back(1.0 / 3.0);
  offsets.push_back(std::sqrt(2.0) - 1.0);
  offsets.push_back(1.0 - 1e-12);
  return offsets;
}

// Sum over all integer nodes j of g(r - j) * phi(r - j).
template <typename Moment>
double node_sum(const DeltaKernel& kernel, double offset, Moment moment) {
  double sum = 0.0;
  for (int node = -kernel.support_width; node <= kernel.support_width; ++node) {
    const double r = offset - node;
    sum += moment(r, node) * kernel.weight_1d(r);
  }
  return sum;
}

class KernelMoments : public ::testing::TestWithParam<std::string> {};

TEST_P(KernelMoments, PartitionOfUnityAndZeroFirstMoment) {
  const DeltaKernel& kernel = find_delta_kernel(GetParam());
  for (const double offset : sample_offsets()) {
    EXPECT_NEAR(node_sum(kernel, offset, [](double, int) { return 1.0; }), 1.0, 1e-15) << offset;
    EXPECT_NEAR(node_sum(kernel, offset, [](double r, int) { return r; }), 0.0, 1e-15) << offset;
  }
}

TEST_P(KernelMoments, NonNegativeSymmetricAndZeroOutsideSupport) {
  const DeltaKernel& kernel = find_delta_kernel(GetParam());
  const double half_width = 0.5 * kernel.support_width;
  for (double r = 0.0; r < half_width + 1.0; r += 1.0 / 128.0) {
    EXPECT_GE(kernel.weight_1d(r), 0.0) << r;
    EXPECT_EQ(kernel.weight_1d(r), kernel.weight_1d(-r)) << r;
    if (r >= half_width) {
      EXPECT_EQ(kernel.weight_1d(r), 0.0) << r;
    }
  }
  EXPECT_GT(kernel.weight_1d(half_width - 1e-3), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Kernels, KernelMoments, ::testing::Values("phi2", "phi3", "phi4"),
                         [](const auto& test_info) { return test_info.param; });

TEST(DeltaKernels, Phi3SumOfSquaresIsOneHalf) {
  const DeltaKernel& kernel = find_delta_kernel("phi3");
  for (const double offset : sample_offsets()) {
    const double squares =
        node_sum(kernel, offset, [&](double r, int) { return kernel.weight_1d(r); });
    EXPECT_NEAR(squares, 0.5, 1e-15) << offset;
  }
}

TEST(DeltaKernels, Phi4EvenOddSplitAndSumOfSquares) {
  const DeltaKernel& kernel = find_delta_kernel("phi4");
  for (const double offset : sample_offsets()) {
    const double even =
        node_sum(kernel, offset, [](double, int node) { return node % 2 == 0 ? 1.0 : 0.0; });
    const double squares =
        node_sum(kernel, offset, [&](double r, int) { return kernel.weight_1d(r); });
    EXPECT_NEAR(even, 0.5, 1e-15) << offset;
    EXPECT_NEAR(squares, 3.0 / 8.0, 1e-15) << offset;
  }
}

TEST(DeltaKernels, RegistryListsEachKernelOnceWithItsSupport) {
  const auto kernels = rbcsim::ibm::delta_kernels();
  ASSERT_EQ(kernels.size(), 3u);
  EXPECT_EQ(find_delta_kernel("phi2").support_width, 2);
  EXPECT_EQ(find_delta_kernel("phi3").support_width, 3);
  EXPECT_EQ(find_delta_kernel("phi4").support_width, 4);
  for (const auto& kernel : kernels) EXPECT_EQ(&find_delta_kernel(kernel.name), &kernel);
}

TEST(DeltaKernels, UnknownNameIsAnInputErrorNamingTheKeyAndTheChoices) {
  expect_input_error_mentioning([] { find_delta_kernel("phi5"); },
                                {"ibm.kernel", "phi5", "phi2, phi3, phi4"});
}

}  // namespace
