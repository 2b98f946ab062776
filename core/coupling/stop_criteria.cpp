#include "coupling/stop_criteria.hpp"

#include <cmath>
#include <span>
#include <stdexcept>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "coupling/coupled_simulation.hpp"

namespace rbcsim::coupling {
namespace {

class TimeLimit final : public StopCriterion {
 public:
  explicit TimeLimit(double time_s) : time_s_(time_s) {}
  std::optional<std::string> check(const CoupledSimulation& simulation) override {
    // The relative slack absorbs the round-off of steps * dt against a time given in seconds.
    if (simulation.time_s() < time_s_ * (1.0 - 1e-12)) return std::nullopt;
    // Often computed (a strain over a shear rate), so its last bits are noise: six digits.
    return "reached the time limit of " + format_significant(time_s_, 6) + " s";
  }

 private:
  double time_s_;
};

class DistanceLimit final : public StopCriterion {
 public:
  DistanceLimit(const CoupledSimulation& simulation, std::size_t cell_index, double distance_um)
      : cell_index_(cell_index),
        start_lu_(simulation.cell(cell_index).centroid_lu()),
        distance_um_(distance_um) {}
  std::optional<std::string> check(const CoupledSimulation& simulation) override {
    const Vec3 displacement_lu = simulation.cell(cell_index_).centroid_lu() - start_lu_;
    const double travelled_um = simulation.frame().dx_um * displacement_lu.norm();
    if (travelled_um < distance_um_) return std::nullopt;
    return "cell " + std::to_string(cell_index_) + " travelled " + format_number(distance_um_) +
           " um";
  }
  void save_state(StateArchive& archive, const std::string& prefix) const override {
    archive.put(prefix + "start_lu", std::span<const Vec3>(&start_lu_, 1));
  }
  void restore_state(StateArchive& archive, const std::string& prefix) override {
    archive.take(prefix + "start_lu", std::span<Vec3>(&start_lu_, 1));
  }

 private:
  std::size_t cell_index_;
  Vec3 start_lu_;
  double distance_um_;
};

class SteadyState final : public StopCriterion {
 public:
  SteadyState(std::string name, std::function<double(const CoupledSimulation&)> observable,
              const SteadyStateTolerance& tolerance)
      : name_(std::move(name)), observable_(std::move(observable)), tolerance_(tolerance) {}

  std::optional<std::string> check(const CoupledSimulation& simulation) override {
    const double now_s = simulation.time_s();
    if (last_check_s_ && now_s - *last_check_s_ < tolerance_.check_interval_s * (1.0 - 1e-12)) {
      return std::nullopt;
    }
    const double value = observable_(simulation);
    if (last_check_s_) {
      const double interval_s = now_s - *last_check_s_;
      const bool steady = std::abs(value - last_value_) <=
                          tolerance_.relative_rate_per_s * std::abs(value) * interval_s;
      steady_checks_ = steady ? steady_checks_ + 1 : 0;
    }
    last_check_s_ = now_s;
    last_value_ = value;
    if (steady_checks_ < tolerance_.consecutive_checks) return std::nullopt;
    return "steady state of " + name_ + " (" + format_significant(value, 6) +
           "; relative change below " + format_number(tolerance_.relative_rate_per_s) +
           " per s over " + std::to_string(steady_checks_) + " checks)";
  }
  // last_check_s, last_value, steady_checks; no check yet: an empty array.
  void save_state(StateArchive& archive, const std::string& prefix) const override {
    archive.put(prefix + "steady_state",
                last_check_s_ ? std::vector<double>{*last_check_s_, last_value_,
                                                    static_cast<double>(steady_checks_)}
                              : std::vector<double>{});
  }
  void restore_state(StateArchive& archive, const std::string& prefix) override {
    const auto saved = archive.take(prefix + "steady_state", std::nullopt);
    if (saved.empty()) return;
    if (saved.size() != 3)
      throw InputError(archive.source(), prefix + "steady_state: not 3 values");
    last_check_s_ = saved[0];
    last_value_ = saved[1];
    steady_checks_ = static_cast<int>(saved[2]);
  }

 private:
  std::string name_;
  std::function<double(const CoupledSimulation&)> observable_;
  SteadyStateTolerance tolerance_;
  std::optional<double> last_check_s_;
  double last_value_ = 0.0;
  int steady_checks_ = 0;
};

void require_positive(double value, const char* what) {
  if (!(value > 0.0)) {
    throw std::invalid_argument(std::string("stop criterion: ") + what + " must be positive");
  }
}

}  // namespace

std::unique_ptr<StopCriterion> stop_at_time(double time_s) {
  require_positive(time_s, "the time limit");
  return std::make_unique<TimeLimit>(time_s);
}

std::unique_ptr<StopCriterion> stop_after_distance(const CoupledSimulation& simulation,
                                                   std::size_t cell_index, double distance_um) {
  require_positive(distance_um, "the distance");
  return std::make_unique<DistanceLimit>(simulation, cell_index, distance_um);
}

std::unique_ptr<StopCriterion> stop_at_steady_state(
    std::string name, std::function<double(const CoupledSimulation&)> observable,
    const SteadyStateTolerance& tolerance) {
  require_positive(tolerance.relative_rate_per_s, "the relative rate");
  require_positive(tolerance.check_interval_s, "the check interval");
  if (tolerance.consecutive_checks < 1) {
    throw std::invalid_argument("stop criterion: at least one steady check is needed");
  }
  return std::make_unique<SteadyState>(std::move(name), std::move(observable), tolerance);
}

}  // namespace rbcsim::coupling
