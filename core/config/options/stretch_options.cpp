#include "cases/contact_patches.hpp"
#include "cases/relaxation_methods.hpp"
#include "cases/stretch_case.hpp"
#include "config/options/option_areas.hpp"

namespace rbcsim::config {
namespace {

// The defaults come from the case's settings struct: one source of truth.
const cases::StretchSettings kStretchDefaults{};

void add_contact_options(OptionTable& table) {
  table.add_choice("stretch.contact.rule", cases::contact_rule_names(),
                   kStretchDefaults.contact.rule,
                   "Which vertices the tweezers hold at each end of the pull axis: those within "
                   "the contact diameter of the end vertex, or a fixed number of extreme vertices "
                   "(HemoCell).");
  table
      .add_number("stretch.contact.diameter_um", "um", kStretchDefaults.contact.diameter_um,
                  "Bead contact diameter of the contact-diameter rule (Mills et al. 2004: 2 um).")
      .above(0.0);
  table
      .add_integer("stretch.contact.extreme_vertex_count", "",
                   kStretchDefaults.contact.extreme_vertex_count,
                   "Vertices per patch of the extreme-vertices rule (HemoCell: 7).")
      .at_least(1);
  table.add_boolean("stretch.contact.rigid", kStretchDefaults.contact.rigid,
                    "The bead holds its contact patch rigid: the patch translates as one body "
                    "(Mills et al. 2004). false: each patch vertex moves under its share of the "
                    "force alone (HemoCell).");
}

void add_quasi_static_options(OptionTable& table) {
  table.add_choice("stretch.quasi_static.relaxation", cases::relaxation_method_names(),
                   kStretchDefaults.relaxation,
                   "Membrane-only relaxation to equilibrium at each force.");
  table
      .add_number("stretch.quasi_static.force_tolerance_pN", "pN",
                  kStretchDefaults.relaxation_settings.force_tolerance_pN,
                  "Equilibrium reached when the largest net vertex force (membrane + tweezers) "
                  "is below this.")
      .above(0.0);
  table
      .add_integer("stretch.quasi_static.max_iterations", "",
                   static_cast<int>(kStretchDefaults.relaxation_settings.max_iterations),
                   "Relaxation iterations allowed per force; reaching it fails the run.")
      .at_least(1);
}

void add_fluid_options(OptionTable& table) {
  const auto& fluid = kStretchDefaults.fluid;
  // Plasma's by default: the equilibrium does not depend on it and the steps to reach it grow as
  // nu^2, but a third of it already went unstable at 50 pN (docs/validation.md, stretch).
  table
      .add_number("stretch.fluid.kinematic_viscosity_m2_per_s", "m^2/s",
                  fluid.lattice.kinematic_viscosity_m2_per_s,
                  "Kinematic viscosity of the stretch's fluid (not physics.plasma_*): the steady "
                  "shapes do not depend on it, the number of steps to reach them grows as its "
                  "square.")
      .above(0.0);
  table
      .add_number("stretch.fluid.box_margin_um", "um", fluid.box_margin_um,
                  "Gap between the resting cell and the periodic box on every side; along the "
                  "pull axis the box also holds the cell at twice its rest length.")
      .above(0.0);
  table
      .add_number("stretch.fluid.force_ramp_time_s", "s", fluid.force_ramp_time_s,
                  "The tweezers move from one force to the next linearly over this time (a jump "
                  "strains the membrane at the patch beyond its force laws at low viscosity).")
      .at_least(0.0);
  table.add_boolean(
      "stretch.fluid.warm_start", fluid.warm_start,
      "Start each force from the membrane's equilibrium under it (the relaxation of "
      "stretch.quasi_static.*) instead of ramping to it: the coupled run "
      "only settles the difference, and its steady state still makes the point. A relaxation "
      "that does not converge leaves the shape and ramps the force.");
  table
      .add_number("stretch.fluid.steady_relative_rate_per_s", "1/s",
                  fluid.steady.relative_rate_per_s,
                  "A force's shape is steady when both diameters change by less than this "
                  "fraction of themselves per second, over three checks in a row.")
      .above(0.0);
  table
      .add_number("stretch.fluid.steady_check_interval_s", "s", fluid.steady.check_interval_s,
                  "Simulated time between two checks of the steady state.")
      .above(0.0);
  table
      .add_number("stretch.fluid.max_time_per_force_s", "s", fluid.max_time_per_force_s,
                  "Simulated time allowed per force; a force not steady by then is reported "
                  "(converged: false, the run fails after the last force).")
      .above(0.0);
  table
      .add_number("stretch.fluid.snapshot_interval_s", "s", fluid.snapshot_interval_s,
                  "Membrane time series every so often (vtk/ and cell0.pvd, or h5/ and "
                  "cells.xdmf as output.format says); 0: only the shape at each force.")
      .at_least(0.0);
}

}  // namespace

void add_stretch_options(OptionTable& table) {
  table.add_choice("stretch.mode", cases::stretch_mode_names(), kStretchDefaults.mode,
                   "How each force reaches its steady shape (quasi-static: the membrane alone "
                   "relaxed to equilibrium, no fluid; fluid: the cell in fluid at rest, LBM + "
                   "IBM, each force run to a steady state).");
  table.add_string("stretch.forces_pN", "mills2004",
                   "Total force on each contact patch, pN: \"mills2004\" (the 13 forces of the "
                   "reference data) or a range list such as \"0:200:25\" or \"0,50,100\".");
  add_contact_options(table);
  add_quasi_static_options(table);
  add_fluid_options(table);
}

}  // namespace rbcsim::config
