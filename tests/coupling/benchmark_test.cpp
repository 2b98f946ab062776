// The measurements behind `rbcsim bench` run, give sane numbers and leave the OpenMP set-up as
// they found it. Speed itself is reported by `rbcsim bench`, never asserted here.
#include "coupling/benchmark.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "common/errors.hpp"
#include "coupling_fixtures.hpp"

namespace rbcsim::coupling {
namespace {

TEST(Benchmark, LatticeBeyondCacheHoldsTwiceTheCacheInFluidArrays) {
  EXPECT_EQ(lattice_beyond_cache(0), (std::array<int, 3>{256, 128, 128}));
  const std::size_t cache = std::size_t{480} << 20;
  const auto extent = lattice_beyond_cache(cache);
  EXPECT_EQ(extent[1], 128);
  EXPECT_EQ(extent[2], 128);
  EXPECT_EQ(extent[0] % 8, 0);
  // 19 populations, density, 3 velocity and 3 force components: 26 doubles per node.
  const auto bytes = [](int nx) { return std::size_t(nx) * 128 * 128 * 26 * sizeof(double); };
  EXPECT_GE(bytes(extent[0]), 2 * cache);
  EXPECT_LT(bytes(extent[0] - 8), 2 * cache);     // the smallest such multiple of 8
  EXPECT_EQ(lattice_beyond_cache(1024)[0], 128);  // never below 128 along x
}

TEST(Benchmark, TriadBandwidthIsPositiveAndRestoresTheThreadCount) {
  const int threads_before = omp_get_max_threads();
  const double bandwidth = measure_triad_bandwidth_GB_per_s(std::size_t{1} << 18, 1);
  EXPECT_TRUE(std::isfinite(bandwidth));
  EXPECT_GT(bandwidth, 0.0);
  EXPECT_EQ(omp_get_max_threads(), threads_before);
  EXPECT_THROW(measure_triad_bandwidth_GB_per_s(100, 0), std::invalid_argument);
  EXPECT_THROW(measure_triad_bandwidth_GB_per_s(0, 1), std::invalid_argument);
}

TEST(Benchmark, MachineDescriptionReadsTheEnvironment) {
  const auto machine = describe_machine();
  EXPECT_FALSE(machine.cpu_model.empty());
  EXPECT_GE(machine.logical_cpus, 1);
  EXPECT_GE(machine.openmp_max_threads, 1);
  const char* policy = std::getenv("OMP_WAIT_POLICY");
  EXPECT_EQ(machine.omp_wait_policy, policy != nullptr ? policy : "unset");
#if defined(__x86_64__)
  // The CPU tells its caches on x86-64 even where /sys lists none (a VM's), so the bench's
  // out-of-cache lattice is sized from a measured cache, not the fallback.
  EXPECT_GT(machine.last_level_cache_bytes, 0u);
#endif
}

TEST(Benchmark, CoupledStepTimingCoversEveryPhase) {
  const int threads_before = omp_get_max_threads();
  const auto sphere = testing::sphere_mesh(1, 1.0, Vec3::Zero());
  const auto timing = measure_coupled_step(sphere, membrane::MembraneParameters{},
                                           testing::plasma_units(), {10, 10, 10}, "phi2", 1);
  EXPECT_EQ(timing.vertex_count, 42u);
  EXPECT_GT(timing.ms_per_step, 0.0);
  // The phases of the fastest batch add up to it (the step's bookkeeping outside them aside).
  const auto& phases = timing.fastest_batch_phases;
  ASSERT_GT(phases.steps, 0u);
  EXPECT_GT(phases.fluid_s, 0.0);
  EXPECT_GT(phases.membrane_s, 0.0);
  EXPECT_NEAR(1e3 * phases.total_s() / static_cast<double>(phases.steps), timing.ms_per_step,
              0.1 * timing.ms_per_step);
  EXPECT_EQ(omp_get_max_threads(), threads_before);
  EXPECT_THROW(measure_coupled_step(sphere, membrane::MembraneParameters{}, testing::plasma_units(),
                                    {10, 10, 10}, "phi9", 1),
               InputError);
}

TEST(Benchmark, SuspensionBlocksPutNeighboursWithinTheContactRange) {
  const auto sphere = testing::sphere_mesh(2, 3.0, Vec3(5.0, -2.0, 1.0));  // 6 um across
  const double dx_um = 0.5;
  const double range_um = 0.75;
  const auto block = suspension_block_nodes(sphere, dx_um, range_um);
  Vec3 low = sphere.positions_um.front(), high = low;
  for (const Vec3& position : sphere.positions_um) {
    low = low.cwiseMin(position);
    high = high.cwiseMax(position);
  }
  // Across the row: the cell plus 2 nodes either side, for a 4-point kernel.
  for (const int axis : {1, 2}) {
    EXPECT_GE(block[axis] * dx_um, high[axis] - low[axis] + 4 * dx_um);
    EXPECT_LT(block[axis] * dx_um, high[axis] - low[axis] + 5 * dx_um);
  }
  // Along it the gap between neighbours' bounding boxes lies in [range / 2, range / 2 + dx).
  const double gap_um = block[0] * dx_um - (high.x() - low.x());
  EXPECT_GE(gap_um, 0.5 * range_um);
  EXPECT_LT(gap_um, 0.5 * range_um + dx_um);
}

TEST(Benchmark, SuspensionTimingPlacesEveryCellAndRefusesNone) {
  const int threads_before = omp_get_max_threads();
  const auto sphere = testing::sphere_mesh(1, 1.0, Vec3::Zero());
  const auto units = testing::plasma_units();
  const contact::ContactParameters contact{5.0, 0.75};
  const auto timing =
      measure_suspension_step(sphere, membrane::MembraneParameters{}, units, contact, 3, "phi2", 1);
  EXPECT_EQ(timing.cell_count, 3u);
  EXPECT_EQ(timing.vertex_count, 3 * 42u);
  const auto block = suspension_block_nodes(sphere, 1e6 * units.dx_m(), contact.range_um);
  EXPECT_EQ(timing.lattice, (std::array<int, 3>{3 * block[0], block[1], block[2]}));
  EXPECT_GT(timing.ms_per_step, 0.0);
  EXPECT_GT(timing.fastest_batch_phases.contact_s, 0.0);
  EXPECT_EQ(omp_get_max_threads(), threads_before);
  EXPECT_THROW(
      measure_suspension_step(sphere, membrane::MembraneParameters{}, units, contact, 0, "phi2", 1),
      InputError);
}

}  // namespace
}  // namespace rbcsim::coupling
