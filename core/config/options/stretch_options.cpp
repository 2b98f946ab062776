#include "cases/contact_patches.hpp"
#include "cases/relaxation_methods.hpp"
#include "cases/stretch_case.hpp"
#include "config/options/option_areas.hpp"

namespace rbcsim::config {
namespace {

// The defaults come from the case's settings struct: one source of truth.
const cases::StretchSettings kDefaults{};

void add_contact_options(OptionTable& table) {
  table.add_choice("stretch.contact.rule", cases::contact_rule_names(), kDefaults.contact.rule,
                   "Which vertices the tweezers hold at each end of the pull axis: those within "
                   "the contact diameter of the end vertex, or a fixed number of extreme vertices "
                   "(HemoCell).");
  table
      .add_number("stretch.contact.diameter_um", "um", kDefaults.contact.diameter_um,
                  "Bead contact diameter of the contact-diameter rule (Mills et al. 2004: 2 um).")
      .above(0.0);
  table
      .add_integer("stretch.contact.extreme_vertex_count", "",
                   kDefaults.contact.extreme_vertex_count,
                   "Vertices per patch of the extreme-vertices rule (HemoCell: 7).")
      .at_least(1);
}

void add_quasi_static_options(OptionTable& table) {
  table.add_choice("stretch.quasi_static.relaxation", cases::relaxation_method_names(),
                   kDefaults.relaxation, "Membrane-only relaxation to equilibrium at each force.");
  table
      .add_number("stretch.quasi_static.force_tolerance_pN", "pN",
                  kDefaults.relaxation_settings.force_tolerance_pN,
                  "Equilibrium reached when the largest net vertex force (membrane + tweezers) "
                  "is below this.")
      .above(0.0);
  table
      .add_integer("stretch.quasi_static.max_iterations", "",
                   static_cast<int>(kDefaults.relaxation_settings.max_iterations),
                   "Relaxation iterations allowed per force; reaching it fails the run.")
      .at_least(1);
}

}  // namespace

void add_stretch_options(OptionTable& table) {
  table.add_choice("stretch.mode", cases::stretch_mode_names(), kDefaults.mode,
                   "How each force reaches its steady shape (quasi-static: the membrane alone "
                   "relaxed to equilibrium, no fluid).");
  table.add_string("stretch.forces_pN", "mills2004",
                   "Total force on each contact patch, pN: \"mills2004\" (the 13 forces of the "
                   "reference data) or a range list such as \"0:200:25\" or \"0,50,100\".");
  add_contact_options(table);
  add_quasi_static_options(table);
}

}  // namespace rbcsim::config
