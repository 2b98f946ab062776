// Small conversions shared by the cases' result.json sections.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

#include "coupling/coupled_simulation.hpp"

namespace rbcsim::cases {

// The number, or JSON null when there is none (a quantity that was not measured).
inline nlohmann::ordered_json optional_number(const std::optional<double>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

// Where a run's coupled steps spent their wall time: each phase in ms per step
// (coupling::ms_per_step_by_phase) and "timed_steps". A measurement, not a result: it sits beside
// wall_time_s at the top of result.json, out of the objects that runs compare bit for bit.
inline nlohmann::ordered_json phase_ms_per_step_json(const coupling::StepPhaseTimes& times) {
  auto phases = nlohmann::ordered_json::object();
  for (const auto& [phase, ms] : coupling::ms_per_step_by_phase(times)) phases[phase] = ms;
  phases["timed_steps"] = times.steps;
  return phases;
}

}  // namespace rbcsim::cases
