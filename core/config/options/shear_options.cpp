#include "cases/shear_case.hpp"
#include "config/options/option_areas.hpp"

namespace rbcsim::config {
namespace {

// The defaults come from the case's settings struct: one source of truth.
const cases::ShearSettings kShearDefaults{};

void add_box_options(OptionTable& table) {
  table.add_choice("shear.boundary", cases::shear_boundary_names(), kShearDefaults.boundary,
                   "Boundary along the velocity gradient: Lees-Edwards sliding periodic images "
                   "(the paper's set-up) or two moving bounce-back walls.");
  // 3 diameters: far enough from the walls (or the sliding images) not to confine the cell;
  // HemoCell's 10 um gap is known to confine it too much.
  table
      .add_number("shear.gap_diameters", "", kShearDefaults.gap_diameters,
                  "Box height (lees-edwards) or wall gap (walls), in cell diameters.")
      .above(1.0);
  table
      .add_number("shear.width_diameters", "", kShearDefaults.width_diameters,
                  "Periodic box length along the flow (x) and the vorticity (z), in cell "
                  "diameters.")
      .above(1.0);
}

void add_steady_options(OptionTable& table) {
  table
      .add_number("shear.max_strain", "", kShearDefaults.max_strain,
                  "Shear strain (rate x time) after which a rate that is not steady stops and is "
                  "reported steady: false. The periodic steady state needs two swinging periods "
                  "(11-15 strains each for a discocyte at 500-2000 1/s) after the start-up.")
      .above(0.0);
  table
      .add_number("shear.steady_tolerance_per_strain", "",
                  kShearDefaults.steady_tolerance_per_strain,
                  "Steady when the means of the length and of the breadth over the last window "
                  "(the tracked membrane point's last half turn, one swinging period) differ "
                  "from those over the window before by less than this fraction of themselves "
                  "per unit strain, at three checks in a row.")
      .above(0.0);
  table
      .add_number("shear.check_interval_strain", "", kShearDefaults.check_interval_strain,
                  "Strain between two steady-state checks; the shape is sampled four times per "
                  "check interval (rate_<i>/history.csv), and a window is one check interval at "
                  "least.")
      .above(0.0);
}

void add_time_scale_options(OptionTable& table) {
  table.add_boolean("shear.viscosity_scaling", kShearDefaults.viscosity_scaling,
                    "Simulate each rate faster with a proportionally lower viscosity (the same "
                    "capillary number, so the same steady shape) up to shear.max_reynolds_number: "
                    "fewer steps per strain at low rates.");
  table
      .add_number("shear.max_reynolds_number", "", kShearDefaults.max_reynolds_number,
                  "Largest cell Reynolds number rate R^2 / nu the viscosity scaling may reach "
                  "(Stokes flow needs << 1).")
      .above(0.0);
}

}  // namespace

void add_shear_options(OptionTable& table) {
  table.add_string("shear.rates_per_s", "0:2000",
                   "Shear rates, 1/s: a range list such as \"0:2000:500\", \"0:2000/5\" or "
                   "\"0,1000,2000\" (\"start:stop\" alone means 5 values).");
  add_box_options(table);
  add_steady_options(table);
  add_time_scale_options(table);
}

}  // namespace rbcsim::config
