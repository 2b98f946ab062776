// The one place that converts between physical SI values and lattice units (docs/physics.md,
// "Units").
//
// Lattice units take the lattice spacing dx, the time step dt and the fluid density rho as 1.
// dt is not chosen freely: the lattice Boltzmann viscosity nu_lattice = (tau - 1/2)/3 must equal
// the physical nu dt / dx^2, so dt = (tau - 1/2)/3 * dx^2 / nu. Every other scale follows from
// dx, dt and rho by dimensional analysis (force = rho dx^4 / dt^2, pressure = rho dx^2 / dt^2,
// ...). Lattice units exist only inside the engine: every interface speaks SI with the unit in the
// name.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rbcsim::units {

// The four physical inputs that fix the lattice (config keys lattice.spacing_um,
// lattice.relaxation_time, physics.plasma_density_kg_per_m3,
// physics.plasma_kinematic_viscosity_m2_per_s).
struct LatticeParameters {
  double spacing_um;
  double relaxation_time;
  double density_kg_per_m3;
  double kinematic_viscosity_m2_per_s;
};

// The physical unit of a value handed to to_lattice() or asked of to_physical().
enum class PhysicalUnit {
  length_m,
  length_um,
  time_s,
  velocity_m_per_s,
  force_N,
  force_pN,
  force_density_N_per_m3,
  density_kg_per_m3,
  pressure_Pa,
  kinematic_viscosity_m2_per_s,
  shear_rate_per_s,
};

// A value derived from the lattice parameters; the name carries the unit (e.g. "dt_s").
struct DerivedValue {
  std::string name;
  double value;
};

// The smallest tau - 1/2 accepted: closer to 1/2 the BGK/TRT collision is unstable.
inline constexpr double kMinimumRelaxationMargin = 1e-3;
// The largest lattice velocity accepted: the lattice Boltzmann method is only weakly
// compressible, and its errors grow with the Mach number u / c_s (c_s = 1/sqrt(3) in lattice
// units).
inline constexpr double kMaximumLatticeVelocity = 0.1;

class UnitConverter {
 public:
  // Throws InputError, naming the config key, for a non-positive spacing, density or viscosity and
  // for tau <= 1/2 or tau < 1/2 + kMinimumRelaxationMargin.
  explicit UnitConverter(const LatticeParameters& parameters);

  double dx_m() const { return dx_m_; }
  double dt_s() const { return dt_s_; }
  double relaxation_time() const { return relaxation_time_; }
  // nu dt / dx^2 = (tau - 1/2) / 3.
  double lattice_kinematic_viscosity() const;

  double to_lattice(PhysicalUnit unit, double physical_value) const;
  double to_physical(PhysicalUnit unit, double lattice_value) const;

  // Converts a physical speed to lattice units and throws InputError(what, ...) when it exceeds
  // kMaximumLatticeVelocity in magnitude. `what` names the config key or quantity checked.
  double check_lattice_velocity(double velocity_m_per_s, std::string_view what) const;

  // Every scale of the lattice, in SI, for `config show` and the run's config.json.
  std::vector<DerivedValue> derived_values() const;

 private:
  // How many SI units of `unit` one lattice unit of the same quantity is.
  double scale(PhysicalUnit unit) const;

  double dx_m_ = 0.0;
  double dt_s_ = 0.0;
  double density_kg_per_m3_ = 0.0;
  double relaxation_time_ = 0.0;
};

}  // namespace rbcsim::units
