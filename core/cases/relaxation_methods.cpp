#include "cases/relaxation_methods.hpp"

#include <array>

#include "cases/fire_relaxation.hpp"
#include "common/registry.hpp"

namespace rbcsim::cases {
namespace {

struct RelaxationEntry {
  std::string_view name;
  RelaxationMethod relax;
};

constexpr std::array<RelaxationEntry, 2> kRelaxationMethods{{
    {"fire", relax_membrane_fire},
    {"euler", membrane::relax_membrane},
}};

}  // namespace

std::vector<std::string> relaxation_method_names() { return entry_names(kRelaxationMethods); }

RelaxationMethod find_relaxation_method(std::string_view name) {
  return find_entry(kRelaxationMethods, name, "stretch.quasi_static.relaxation").relax;
}

}  // namespace rbcsim::cases
