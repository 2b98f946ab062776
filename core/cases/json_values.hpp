// Small conversions shared by the cases' result.json sections.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "common/errors.hpp"

#include "coupling/coupled_simulation.hpp"

namespace rbcsim::cases {

// The number, or JSON null when there is none (a quantity that was not measured).
inline nlohmann::ordered_json optional_number(const std::optional<double>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

// The number, or JSON null when it is not finite (JSON has no NaN or infinity).
inline nlohmann::ordered_json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

// Where a run's coupled steps spent their wall time: each phase in ms per step
// (coupling::ms_per_step_by_phase) and "timed_steps". A measurement, not a result: it sits beside
// wall_time_s at the top of result.json, out of the objects that runs compare bit for bit.
inline nlohmann::ordered_json phase_ms_per_step_json(const coupling::StepPhaseTimes& times) {
  auto phases = nlohmann::ordered_json::object();
  for (const auto& [phase, ms] : coupling::ms_per_step_by_phase(times)) phases[phase] = ms;
  phases["timed_steps"] = times.steps;
  // With membrane viscosity: the conjugate-gradient iterations of an implicit friction solve, on
  // average (what its time is made of; docs/performance.md).
  if (times.friction_solves > 0) {
    phases["friction_solves"] = times.friction_solves;
    phases["friction_iterations_per_solve"] =
        static_cast<double>(times.friction_iterations) / static_cast<double>(times.friction_solves);
  }
  return phases;
}

// ibm.sub_spacing_drag as the run used it (coupling::SubSpacingDragSummary); null when it was off.
// viscosity_raised_by is how much stronger than the fluids' drag the raised cells' was.
inline nlohmann::ordered_json sub_spacing_drag_json(const coupling::SubSpacingDragSummary& drag) {
  if (!drag.on) return nullptr;
  return {{"fastest_rate_per_step", drag.fastest_rate_per_step},
          {"limit_rate_per_step", coupling::Cell::kMaxDragRatePerStep},
          {"raised_cells", drag.raised_cells},
          {"viscosity_raised_by", drag.viscosity_raised_by}};
}

// A number of a record a run wrote (a finished rate's point.json, say); null (written for a
// non-finite one) reads as NaN. InputError naming `source` if missing or not a number.
inline double record_number(const nlohmann::json& record, const char* key,
                            const std::string& source) {
  if (!record.contains(key)) throw InputError(source, std::string("no \"") + key + "\"");
  const auto& value = record.at(key);
  if (value.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!value.is_number()) throw InputError(source, std::string("\"") + key + "\" is not a number");
  return value.get<double>();
}

// The summary back from sub_spacing_drag_json (a record a run wrote; null: off). InputError
// naming `source` for a missing or non-numeric figure.
inline coupling::SubSpacingDragSummary sub_spacing_drag_from_json(const nlohmann::json& drag,
                                                                  const std::string& source) {
  if (drag.is_null()) return {};
  if (!drag.is_object()) throw InputError(source, "\"sub_spacing_drag\" is not an object or null");
  const double raised_cells = record_number(drag, "raised_cells", source);
  if (!(raised_cells >= 0.0) || raised_cells != std::floor(raised_cells)) {
    throw InputError(source, "\"raised_cells\" is not a count");
  }
  return {.on = true,
          .fastest_rate_per_step = record_number(drag, "fastest_rate_per_step", source),
          .raised_cells = static_cast<std::size_t>(raised_cells),
          .viscosity_raised_by = record_number(drag, "viscosity_raised_by", source)};
}

}  // namespace rbcsim::cases
