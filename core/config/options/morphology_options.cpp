#include <string>
#include <vector>

#include "config/embedded_share.hpp"
#include "config/options/option_areas.hpp"
#include "shapes/sequence.hpp"

namespace rbcsim::config {
namespace {

// A preset is a whole parameter set, share/config/presets/<name>.json, in this order.
std::vector<std::string> presets() {
  std::vector<std::string> names;
  for (const char* name : {"paper", "physiological"}) {
    if (find_embedded_share_file(std::string("config/presets/") + name + ".json")) {
      names.emplace_back(name);
    }
  }
  return names;
}

}  // namespace

// The two tables decide the choices together, never a list here.
std::vector<std::string> morphology_choices() {
  std::vector<std::string> names;
  for (const auto& shape : shapes::shape_sequence().entries()) {
    const std::string name(shape.name);
    if (find_embedded_share_file("config/" + name + ".json")) names.push_back(name);
  }
  return names;
}

void add_morphology_options(OptionTable& table) {
  table.add_choice("morphology", morphology_choices(), "discocyte",
                   "Cell morphology: selects the built-in shape and its Table 2 stiffnesses.");
  table.add_choice("preset", presets(), "paper",
                   "Whole parameter set under the morphology's and the user's settings: paper (the "
                   "paper's six forces as printed, plasma inside the cell, no membrane "
                   "viscosity) or physiological (Helfrich bending in place of Eq. 7, plus the "
                   "bilayer's area incompressibility, whole and per triangle, membrane viscosity "
                   "and a cytoplasm five times as viscous as plasma; docs/physics.md).");
}

}  // namespace rbcsim::config
