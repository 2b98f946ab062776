#include "config/options/option_areas.hpp"
#include "lattice/fluid_solver.hpp"

namespace rbcsim::config {

void add_physics_options(OptionTable& table) {
  // HemoCell's plasma values (docs/physics.md, "Units") and the paper's kBT (Table 2).
  table.add_number("physics.plasma_density_kg_per_m3", "kg/m^3", 1025.0, "Density of the plasma.")
      .above(0.0);
  table
      .add_number("physics.plasma_kinematic_viscosity_m2_per_s", "m^2/s", 1.1e-6,
                  "Kinematic viscosity of the plasma (or of the suspending medium).")
      .above(0.0);
  // share/reference: cytosol ~6-7 mPa s against plasma ~1.2 mPa s, HemoCell's viscosityRatio 5.
  // The default 1 is the paper's single fluid (no indicator, the uniform kernels).
  table
      .add_number("physics.cytoplasm_viscosity_ratio", "",
                  lattice::FluidParameters{}.inner_viscosity_ratio,
                  "Viscosity of the fluid inside every cell over that of the plasma (physiological "
                  "~5: haemoglobin solution ~6-7 mPa s, plasma ~1.2 mPa s); 1: one fluid.")
      .above(0.0);
  table
      .add_number("physics.thermal_energy_J", "J", 4.100531391e-21,
                  "Thermal energy kBT, the unit of every membrane stiffness k (Table 2).")
      .above(0.0);
}

}  // namespace rbcsim::config
