// Observers and stop criteria of the coupled run: who is called when, and when a run stops.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/coupled_simulation.hpp"
#include "coupling_fixtures.hpp"

namespace rbcsim::coupling {
namespace {

using testing::periodic_fluid;
using testing::plasma_units;
using testing::sphere_mesh;

// A tiny simulation: one 42-vertex sphere at rest in an 8^3 periodic box.
std::unique_ptr<CoupledSimulation> tiny_simulation() {
  auto simulation = std::make_unique<CoupledSimulation>(periodic_fluid(8, 8, 8), plasma_units(),
                                                        CouplingParameters{});
  const auto sphere = sphere_mesh(1, 1.0, Vec3(1.8, 1.7, 1.9));
  simulation->add_cell(membrane::MembraneModel(sphere, membrane::MembraneParameters{}),
                       sphere.positions_um);
  return simulation;
}

TEST(RunControl, ObserversSeeTheInitialStateEveryIntervalAndTheFinalState) {
  auto simulation = tiny_simulation();
  std::vector<std::size_t> seen;
  simulation->add_observer(
      {"steps", 3, [&](const CoupledSimulation& s) { seen.push_back(s.time_step()); }});
  const double dt_s = plasma_units().dt_s();
  simulation->add_stop_criterion(stop_at_time(10 * dt_s));
  const auto summary = simulation->run();
  EXPECT_EQ(summary.steps, 10u);
  EXPECT_NEAR(summary.time_s, 10 * dt_s, 1e-12 * dt_s);
  EXPECT_EQ(summary.stop_reason.rfind("reached the time limit", 0), 0u);
  EXPECT_EQ(seen, (std::vector<std::size_t>{0, 3, 6, 9, 10}));
  EXPECT_EQ(summary.capped_steps_per_cell, std::vector<std::size_t>{0});
}

TEST(RunControl, RefusesDuplicateObserversZeroIntervalsAndRunsWithoutStop) {
  auto simulation = tiny_simulation();
  const auto nothing = [](const CoupledSimulation&) {};
  simulation->add_observer({"a", 1, nothing});
  EXPECT_THROW(simulation->add_observer({"a", 2, nothing}), std::invalid_argument);
  EXPECT_THROW(simulation->add_observer({"b", 0, nothing}), std::invalid_argument);
  EXPECT_THROW(simulation->run(), std::logic_error);
  EXPECT_THROW(stop_at_time(0.0), std::invalid_argument);
  EXPECT_THROW(stop_after_distance(*simulation, 0, -1.0), std::invalid_argument);
  EXPECT_THROW(stop_after_distance(*simulation, 3, 1.0), std::out_of_range);
}

TEST(RunControl, SteadyStateStopsOnceTheRelativeRateStaysBelowTheTolerance) {
  // q(t) = 1 + exp(-t / T) relaxes at the relative rate r(t) = exp(-t/T) / (T (1 + exp(-t/T))),
  // which falls below the tolerance at t* = -T ln(rate T / (1 - rate T)).
  auto simulation = tiny_simulation();
  const double dt_s = plasma_units().dt_s();
  const double relaxation_s = 20 * dt_s;
  const double rate_per_s = 0.01 / relaxation_s;
  const double interval_s = 4 * dt_s;
  simulation->add_stop_criterion(stop_at_steady_state(
      "q", [&](const CoupledSimulation& s) { return 1.0 + std::exp(-s.time_s() / relaxation_s); },
      {rate_per_s, interval_s, 3}));
  const auto summary = simulation->run();
  const double x = rate_per_s * relaxation_s;
  const double steady_from_s = -relaxation_s * std::log(x / (1.0 - x));
  // A finite difference over an interval lags the derivative by up to one interval; then three
  // steady checks in a row are needed.
  EXPECT_GE(summary.time_s, steady_from_s - interval_s);
  EXPECT_LE(summary.time_s, steady_from_s + 4 * interval_s + dt_s);
  EXPECT_EQ(summary.stop_reason.rfind("steady state of q", 0), 0u);
}

TEST(RunControl, ExternalForceHooksAddUpEveryStep) {
  auto simulation = tiny_simulation();
  simulation->add_external_force([](std::size_t cell, const Cell&, std::span<Vec3> forces_pN) {
    EXPECT_EQ(cell, 0u);
    forces_pN[1] += Vec3(1.0, 0.0, 0.0);
  });
  simulation->add_external_force([](std::size_t, const Cell&, std::span<Vec3> forces_pN) {
    forces_pN[1] += Vec3(0.0, 2.0, 0.0);
  });
  simulation->step();
  simulation->step();
  const Cell& cell = simulation->cell(0);
  // Zeroed before the hooks each step: the two hooks' sum, not twice it.
  EXPECT_EQ(cell.external_forces_pN()[1], Vec3(1.0, 2.0, 0.0));
  EXPECT_EQ(cell.external_forces_pN()[0], Vec3::Zero());
  EXPECT_EQ(cell.total_forces_pN()[1], cell.membrane_forces().total_pN[1] + Vec3(1.0, 2.0, 0.0));
}

TEST(RunControl, PhaseTimesAddUpToTheSteps) {
  auto simulation = tiny_simulation();
  for (int step = 0; step < 5; ++step) simulation->step();
  const auto& times = simulation->phase_times();
  EXPECT_EQ(times.steps, 5u);
  EXPECT_GT(times.fluid_s, 0.0);
  EXPECT_GT(times.membrane_s, 0.0);
  EXPECT_DOUBLE_EQ(times.total_s(), times.membrane_s + times.contact_s + times.spread_s + times.indicator_s +
                                        times.fluid_s + times.friction_s + times.advance_s +
                                        times.checks_s + times.observers_s);
  simulation->reset_phase_times();
  EXPECT_EQ(simulation->phase_times().steps, 0u);
}

}  // namespace
}  // namespace rbcsim::coupling
