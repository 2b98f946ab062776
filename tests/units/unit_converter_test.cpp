#include "units/unit_converter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "common/errors.hpp"

namespace {

using rbcsim::InputError;
using rbcsim::units::LatticeParameters;
using rbcsim::units::PhysicalUnit;
using rbcsim::units::UnitConverter;

constexpr double kNotANumber = std::numeric_limits<double>::quiet_NaN();
// docs/physics.md, "Units": dx = 0.5 um, tau = 1, HemoCell's plasma.
constexpr LatticeParameters kPlasma{0.5, 1.0, 1025.0, 1.1e-6};
// By hand: dt = (tau - 1/2)/3 * dx^2 / nu = (1/6) * (5e-7 m)^2 / 1.1e-6 m^2/s = 3.7879e-8 s.
constexpr double kHandTimeStep_s = (0.5 / 3.0) * 2.5e-13 / 1.1e-6;

std::string message_of(const LatticeParameters& parameters) {
  try {
    UnitConverter converter(parameters);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(UnitConverter, TimeStepOfTheHandComputedExample) {
  const UnitConverter converter(kPlasma);
  EXPECT_NEAR(converter.dt_s(), 3.7879e-8, 0.00005e-8);  // the 5 digits computed by hand
  EXPECT_DOUBLE_EQ(converter.dt_s(), kHandTimeStep_s);
  EXPECT_DOUBLE_EQ(converter.dx_m(), 5e-7);
  EXPECT_DOUBLE_EQ(converter.lattice_kinematic_viscosity(), 1.0 / 6.0);
}

TEST(UnitConverter, LatticeViscosityIsNuDtOverDxSquared) {
  // The defining relation of dt, checked through the public conversion for another tau.
  const UnitConverter converter({0.25, 0.8, 1025.0, 1.1e-6});
  EXPECT_DOUBLE_EQ(converter.to_lattice(PhysicalUnit::kinematic_viscosity_m2_per_s, 1.1e-6), 0.1);
}

TEST(UnitConverter, ScalesFollowFromDxDtRho) {
  const UnitConverter converter(kPlasma);
  const double dx = 5e-7;
  const double dt = kHandTimeStep_s;
  const double rho = 1025.0;
  EXPECT_DOUBLE_EQ(converter.to_lattice(PhysicalUnit::length_um, 0.25), 0.5);
  EXPECT_DOUBLE_EQ(converter.to_lattice(PhysicalUnit::length_m, 2e-6), 4.0);
  EXPECT_DOUBLE_EQ(converter.to_lattice(PhysicalUnit::time_s, 10 * dt), 10.0);
  EXPECT_DOUBLE_EQ(converter.to_lattice(PhysicalUnit::velocity_m_per_s, 0.04), 0.04 * dt / dx);
  EXPECT_DOUBLE_EQ(converter.to_lattice(PhysicalUnit::shear_rate_per_s, 1000.0), 1000.0 * dt);
  EXPECT_DOUBLE_EQ(converter.to_lattice(PhysicalUnit::force_N, 50e-12),
                   50e-12 * dt * dt / (rho * dx * dx * dx * dx));
  EXPECT_DOUBLE_EQ(converter.to_lattice(PhysicalUnit::force_pN, 50.0),
                   converter.to_lattice(PhysicalUnit::force_N, 50e-12));
  EXPECT_DOUBLE_EQ(converter.to_lattice(PhysicalUnit::pressure_Pa, 10.0),
                   10.0 * dt * dt / (rho * dx * dx));
  // The lattice density 1 is the plasma's.
  EXPECT_DOUBLE_EQ(converter.to_physical(PhysicalUnit::density_kg_per_m3, 1.02), 1.02 * rho);
  // A force density over one lattice cell is a force.
  EXPECT_DOUBLE_EQ(
      converter.to_lattice(PhysicalUnit::force_density_N_per_m3, 50e-12 / (dx * dx * dx)),
      converter.to_lattice(PhysicalUnit::force_N, 50e-12));
}

TEST(UnitConverter, LatticePressureOfOneThirdIsRhoTimesSoundSpeedSquared) {
  // The lattice equation of state p = c_s^2 rho with c_s^2 = 1/3, in SI.
  const UnitConverter converter(kPlasma);
  const double sound_speed_m_per_s = 5e-7 / kHandTimeStep_s / std::sqrt(3.0);
  EXPECT_DOUBLE_EQ(converter.to_physical(PhysicalUnit::pressure_Pa, 1.0 / 3.0),
                   1025.0 * sound_speed_m_per_s * sound_speed_m_per_s);
}

TEST(UnitConverter, EveryUnitRoundTrips) {
  const UnitConverter converter({0.37, 1.3, 1100.0, 4e-6});
  for (const auto unit :
       {PhysicalUnit::length_m, PhysicalUnit::length_um, PhysicalUnit::time_s,
        PhysicalUnit::velocity_m_per_s, PhysicalUnit::force_N, PhysicalUnit::force_pN,
        PhysicalUnit::force_density_N_per_m3, PhysicalUnit::density_kg_per_m3,
        PhysicalUnit::pressure_Pa, PhysicalUnit::kinematic_viscosity_m2_per_s,
        PhysicalUnit::shear_rate_per_s}) {
    for (const double value : {-3.5e-7, 1.0, 42.0e3}) {
      const double back = converter.to_physical(unit, converter.to_lattice(unit, value));
      EXPECT_NEAR(back, value, 1e-14 * std::abs(value)) << static_cast<int>(unit);
    }
  }
}

TEST(UnitConverter, RejectsRelaxationTimeAtOrBelowOneHalf) {
  const auto message = message_of({0.5, 0.5, 1025.0, 1.1e-6});
  EXPECT_NE(message.find("lattice.relaxation_time"), std::string::npos) << message;
  EXPECT_NE(message.find("must be > 0.5"), std::string::npos) << message;
  EXPECT_NE(message_of({0.5, 0.3, 1025.0, 1.1e-6}), "");
}

TEST(UnitConverter, RejectsRelaxationTimeTooCloseToOneHalf) {
  const auto message = message_of({0.5, 0.5005, 1025.0, 1.1e-6});
  EXPECT_NE(message.find("lattice.relaxation_time"), std::string::npos) << message;
  EXPECT_NE(message.find("too close to 1/2: unstable"), std::string::npos) << message;
  EXPECT_EQ(message_of({0.5, 0.501, 1025.0, 1.1e-6}), "");
}

TEST(UnitConverter, RejectsNonPositiveInputsNamingTheKey) {
  EXPECT_NE(message_of({0.0, 1.0, 1025.0, 1.1e-6}).find("lattice.spacing_um"), std::string::npos);
  EXPECT_NE(message_of({0.5, 1.0, -1.0, 1.1e-6}).find("physics.plasma_density_kg_per_m3"),
            std::string::npos);
  EXPECT_NE(message_of({0.5, 1.0, 1025.0, kNotANumber})
                .find("physics.plasma_kinematic_viscosity_m2_per_s"),
            std::string::npos);
}

TEST(UnitConverter, LatticeVelocityCheck) {
  const UnitConverter converter(kPlasma);
  // The paper's capillary inlet, 0.04 m/s: 0.04 * dt / dx = 0.00303 in lattice units, safe.
  EXPECT_DOUBLE_EQ(converter.check_lattice_velocity(0.04, "capillary inlet"),
                   0.04 * kHandTimeStep_s / 5e-7);
  // 2 m/s is 0.15 in lattice units, above the Mach limit 0.1, in either direction.
  for (const double velocity_m_per_s : {2.0, -2.0, kNotANumber}) {
    try {
      converter.check_lattice_velocity(velocity_m_per_s, "shear.wall_velocity_m_per_s");
      ADD_FAILURE() << velocity_m_per_s << " m/s was accepted";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind("shear.wall_velocity_m_per_s: ", 0), 0u) << message;
      EXPECT_NE(message.find("Mach"), std::string::npos) << message;
    }
  }
}

TEST(UnitConverter, DerivedValuesNameTheirUnits) {
  const UnitConverter converter(kPlasma);
  const auto values = converter.derived_values();
  auto value_of = [&values](const std::string& name) {
    for (const auto& derived : values) {
      if (derived.name == name) return derived.value;
    }
    ADD_FAILURE() << "no derived value " << name;
    return kNotANumber;
  };
  EXPECT_DOUBLE_EQ(value_of("dt_s"), kHandTimeStep_s);
  EXPECT_DOUBLE_EQ(value_of("dx_m"), 5e-7);
  EXPECT_DOUBLE_EQ(value_of("max_safe_velocity_m_per_s"), 0.1 * 5e-7 / kHandTimeStep_s);
  EXPECT_DOUBLE_EQ(value_of("dynamic_viscosity_Pa_s"), 1025.0 * 1.1e-6);
}

}  // namespace
