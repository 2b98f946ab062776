#include "units/unit_converter.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace rbcsim::units {
namespace {

constexpr double kMetresPerMicrometre = 1e-6;
constexpr double kNewtonsPerPiconewton = 1e-12;

void require_positive(double value, const char* key) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(key, "must be a positive number, got " + format_number(value));
  }
}

void require_stable_relaxation_time(double tau) {
  const char* key = "lattice.relaxation_time";
  if (!(tau > 0.5) || !std::isfinite(tau)) {
    throw InputError(key,
                     "tau = " + format_number(tau) +
                         " must be > 0.5 (the lattice viscosity (tau - 1/2)/3 must be positive)");
  }
  if (tau < 0.5 + kMinimumRelaxationMargin) {
    throw InputError(key, "tau = " + format_number(tau) +
                              " is too close to 1/2: unstable (use tau >= " +
                              format_number(0.5 + kMinimumRelaxationMargin) + ")");
  }
}

}  // namespace

UnitConverter::UnitConverter(const LatticeParameters& parameters)
    : relaxation_time_(parameters.relaxation_time) {
  require_positive(parameters.spacing_um, "lattice.spacing_um");
  require_positive(parameters.density_kg_per_m3, "physics.plasma_density_kg_per_m3");
  require_positive(parameters.kinematic_viscosity_m2_per_s,
                   "physics.plasma_kinematic_viscosity_m2_per_s");
  require_stable_relaxation_time(parameters.relaxation_time);
  dx_m_ = parameters.spacing_um * kMetresPerMicrometre;
  density_kg_per_m3_ = parameters.density_kg_per_m3;
  dt_s_ = lattice_kinematic_viscosity() * dx_m_ * dx_m_ / parameters.kinematic_viscosity_m2_per_s;
}

double UnitConverter::lattice_kinematic_viscosity() const { return (relaxation_time_ - 0.5) / 3.0; }

double UnitConverter::scale(PhysicalUnit unit) const {
  const double velocity = dx_m_ / dt_s_;
  const double force_density = density_kg_per_m3_ * dx_m_ / (dt_s_ * dt_s_);
  switch (unit) {
    case PhysicalUnit::length_m:
      return dx_m_;
    case PhysicalUnit::length_um:
      return dx_m_ / kMetresPerMicrometre;
    case PhysicalUnit::time_s:
      return dt_s_;
    case PhysicalUnit::velocity_m_per_s:
      return velocity;
    case PhysicalUnit::force_N:
      return force_density * dx_m_ * dx_m_ * dx_m_;
    case PhysicalUnit::force_pN:
      return force_density * dx_m_ * dx_m_ * dx_m_ / kNewtonsPerPiconewton;
    case PhysicalUnit::force_density_N_per_m3:
      return force_density;
    case PhysicalUnit::density_kg_per_m3:
      return density_kg_per_m3_;
    case PhysicalUnit::pressure_Pa:
      return density_kg_per_m3_ * velocity * velocity;
    case PhysicalUnit::kinematic_viscosity_m2_per_s:
      return dx_m_ * velocity;
    case PhysicalUnit::shear_rate_per_s:
      return 1.0 / dt_s_;
  }
  throw std::logic_error("UnitConverter::scale: unknown PhysicalUnit");
}

double UnitConverter::to_lattice(PhysicalUnit unit, double physical_value) const {
  return physical_value / scale(unit);
}

double UnitConverter::to_physical(PhysicalUnit unit, double lattice_value) const {
  return lattice_value * scale(unit);
}

double UnitConverter::check_lattice_velocity(double velocity_m_per_s, std::string_view what) const {
  const double lattice_velocity = to_lattice(PhysicalUnit::velocity_m_per_s, velocity_m_per_s);
  if (!(std::abs(lattice_velocity) <= kMaximumLatticeVelocity)) {
    throw InputError(std::string(what),
                     format_number(velocity_m_per_s) + " m/s is " +
                         format_number(lattice_velocity) + " in lattice units, above the safe " +
                         format_number(kMaximumLatticeVelocity) +
                         " (Mach limit); lower lattice.relaxation_time or lattice.spacing_um");
  }
  return lattice_velocity;
}

std::vector<DerivedValue> UnitConverter::derived_values() const {
  const double velocity_unit = scale(PhysicalUnit::velocity_m_per_s);
  return {
      {"dx_m", dx_m_},
      {"dt_s", dt_s_},
      {"lattice_kinematic_viscosity", lattice_kinematic_viscosity()},
      {"velocity_unit_m_per_s", velocity_unit},
      {"max_safe_velocity_m_per_s", kMaximumLatticeVelocity * velocity_unit},
      {"speed_of_sound_m_per_s", velocity_unit / std::sqrt(3.0)},
      {"force_unit_pN", scale(PhysicalUnit::force_pN)},
      {"force_density_unit_N_per_m3", scale(PhysicalUnit::force_density_N_per_m3)},
      {"pressure_unit_Pa", scale(PhysicalUnit::pressure_Pa)},
      {"shear_rate_unit_per_s", scale(PhysicalUnit::shear_rate_per_s)},
      {"dynamic_viscosity_Pa_s", density_kg_per_m3_ *
                                     scale(PhysicalUnit::kinematic_viscosity_m2_per_s) *
                                     lattice_kinematic_viscosity()},
  };
}

}  // namespace rbcsim::units
