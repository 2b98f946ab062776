#include "config/options/option_areas.hpp"

namespace rbcsim::config {

void add_morphology_options(OptionTable& table) {
  // Selects the built-in shape and the Table 2 parameter set of share/config/<morphology>.json.
  table.add_choice("morphology", {"discocyte", "stomatocyte-II", "echinocyte-III"}, "discocyte",
                   "Cell morphology: selects the built-in shape and its Table 2 stiffnesses.");
}

}  // namespace rbcsim::config
