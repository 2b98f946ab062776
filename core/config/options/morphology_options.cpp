#include <string>
#include <vector>

#include "config/embedded_share.hpp"
#include "config/options/option_areas.hpp"
#include "shapes/sequence.hpp"

namespace rbcsim::config {
namespace {

// A morphology is a shape of the sequence (shapes/sequence.hpp) that has a Table 2 parameter set,
// share/config/<name>.json: the two tables decide the choices together, never a list here.
std::vector<std::string> morphologies() {
  std::vector<std::string> names;
  for (const auto& shape : shapes::shape_sequence().entries()) {
    const std::string name(shape.name);
    if (find_embedded_share_file("config/" + name + ".json")) names.push_back(name);
  }
  return names;
}

}  // namespace

void add_morphology_options(OptionTable& table) {
  table.add_choice("morphology", morphologies(), "discocyte",
                   "Cell morphology: selects the built-in shape and its Table 2 stiffnesses.");
}

}  // namespace rbcsim::config
