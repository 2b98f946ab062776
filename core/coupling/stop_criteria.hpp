// When a coupled run stops (docs/physics.md: runs go to a steady state): a physical time, a
// distance travelled by a cell, or the steady state of an observable. A run stops at the first
// criterion that holds, and reports its reason.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "common/state_archive.hpp"

namespace rbcsim::coupling {

class CoupledSimulation;

class StopCriterion {
 public:
  virtual ~StopCriterion() = default;
  // Called after every step: why the run should stop now, or nothing.
  virtual std::optional<std::string> check(const CoupledSimulation& simulation) = 0;
  // Checkpoints: a criterion that remembers something (where a cell started, the last values of
  // an observable) saves it as arrays named `<prefix>...`, so a resumed run stops where the
  // uninterrupted one would.
  virtual void save_state(StateArchive& /*archive*/, const std::string& /*prefix*/) const {}
  virtual void restore_state(StateArchive& /*archive*/, const std::string& /*prefix*/) {}
};

// Stops once the simulated time reaches time_s (the step that reaches it is the last).
// Throws std::invalid_argument unless time_s > 0.
std::unique_ptr<StopCriterion> stop_at_time(double time_s);

// Stops once the centroid (mean vertex position) of cell `cell_index` is distance_um away from
// where it is now. Throws std::out_of_range for a missing cell, std::invalid_argument unless
// distance_um > 0.
std::unique_ptr<StopCriterion> stop_after_distance(const CoupledSimulation& simulation,
                                                   std::size_t cell_index, double distance_um);

struct SteadyStateTolerance {
  // Steady when |q(t) - q(t - interval)| <= relative_rate_per_s * |q(t)| * interval: the
  // observable changes by less than this fraction of itself per second of simulated time.
  double relative_rate_per_s = 1.0;
  double check_interval_s = 1e-3;
  // ... for this many checks in a row (one check can fall on the turning point of an oscillation).
  int consecutive_checks = 3;
};

// Stops at the steady state of a scalar observable of the simulation (a diameter, a deformation
// index, an angular velocity). `name` goes into the stop reason. Throws std::invalid_argument for
// a non-positive rate or interval, or fewer than one check.
std::unique_ptr<StopCriterion> stop_at_steady_state(
    std::string name, std::function<double(const CoupledSimulation&)> observable,
    const SteadyStateTolerance& tolerance);

}  // namespace rbcsim::coupling
