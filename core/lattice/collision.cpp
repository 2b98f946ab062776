#include "lattice/collision.hpp"

#include "common/errors.hpp"
#include "common/registry.hpp"

#include <array>
#include <cmath>
#include <string>

namespace rbcsim::lattice {
namespace {

RelaxationRates bgk_rates(const CollisionParameters& parameters) {
  const double omega = 1.0 / parameters.tau;
  return {omega, omega};
}

// tau_odd from Lambda = (tau_even - 1/2)(tau_odd - 1/2).
RelaxationRates trt_rates(const CollisionParameters& parameters) {
  const double tau_odd = 0.5 + parameters.magic_parameter / (parameters.tau - 0.5);
  return {1.0 / parameters.tau, 1.0 / tau_odd};
}

constexpr std::array kCollisionModels = {
    CollisionModel{"bgk", "single relaxation time (Bhatnagar-Gross-Krook)", bgk_rates},
    CollisionModel{"trt", "two relaxation times with magic parameter Lambda", trt_rates},
};

}  // namespace

std::span<const CollisionModel> collision_models() { return kCollisionModels; }

RelaxationRates relaxation_rates(std::string_view model, const CollisionParameters& parameters) {
  if (!(parameters.tau > 0.5)) {
    throw InputError(
        "lattice.relaxation_time",
        "must exceed 1/2 (zero or negative viscosity), got " + std::to_string(parameters.tau));
  }
  if (!(parameters.magic_parameter > 0.0)) {
    throw InputError("lattice.trt_magic",
                     "must be positive, got " + std::to_string(parameters.magic_parameter));
  }
  return find_entry(kCollisionModels, model, "lattice.collision").rates(parameters);
}

ViscosityClass viscosity_class(double indicator) {
  return static_cast<ViscosityClass>(std::lround(indicator * (kViscosityClasses - 1)));
}

std::vector<RelaxationRates> viscosity_class_rates(std::string_view model,
                                                   const CollisionParameters& parameters,
                                                   double viscosity_ratio) {
  if (!(viscosity_ratio > 0.0 && std::isfinite(viscosity_ratio))) {
    throw InputError("physics.cytoplasm_viscosity_ratio",
                     "must be positive and finite, got " + std::to_string(viscosity_ratio));
  }
  std::vector<RelaxationRates> rates;
  rates.reserve(kViscosityClasses);
  rates.push_back(relaxation_rates(model, parameters));
  const double excess = parameters.tau - 0.5;
  for (int k = 1; k < kViscosityClasses; ++k) {
    const double indicator = static_cast<double>(k) / (kViscosityClasses - 1);
    CollisionParameters local = parameters;
    local.tau = 0.5 + excess * (1.0 + (viscosity_ratio - 1.0) * indicator);
    rates.push_back(relaxation_rates(model, local));
  }
  return rates;
}

}  // namespace rbcsim::lattice
