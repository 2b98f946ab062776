#include "config/options/option_areas.hpp"

namespace rbcsim::config {

void add_ibm_options(OptionTable& table) {
  table.add_choice("ibm.kernel", {"phi2", "phi3", "phi4"}, "phi2",
                   "Immersed-boundary kernel: phi2 (trilinear, HemoCell's default), phi3, phi4 "
                   "(Peskin).");
}

}  // namespace rbcsim::config
