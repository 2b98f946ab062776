// The registry of membrane force terms (`membrane.forces`), in evaluation order.
#include <algorithm>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>

#include "membrane/force_terms.hpp"

namespace rbcsim::membrane {
namespace {

constexpr ForceTermEntry kForceTerms[] = {
    {"link",
     [](const MembraneParameters& p, const ReferenceState&) -> std::unique_ptr<ForceTerm> {
       return std::make_unique<LinkTerm>(p);
     }},
    {"bend",
     [](const MembraneParameters& p, const ReferenceState&) -> std::unique_ptr<ForceTerm> {
       return std::make_unique<BendingTerm>(p, find_hinge_distribution(p.distribution));
     }},
    {"area",
     [](const MembraneParameters& p, const ReferenceState&) -> std::unique_ptr<ForceTerm> {
       return std::make_unique<AreaTerm>(p);
     }},
    {"volume",
     [](const MembraneParameters& p, const ReferenceState&) -> std::unique_ptr<ForceTerm> {
       return std::make_unique<VolumeTerm>(p);
     }},
    {"area_difference", make_area_difference_term},
    {"total_curvature", make_total_curvature_term},
};

}  // namespace

std::span<const ForceTermEntry> force_term_table() { return kForceTerms; }

std::vector<std::unique_ptr<ForceTerm>> make_force_terms(std::span<const std::string_view> names,
                                                         const MembraneParameters& parameters,
                                                         const ReferenceState& reference) {
  std::vector<std::unique_ptr<ForceTerm>> terms;
  for (auto name : names) {
    const auto* entry = std::find_if(std::begin(kForceTerms), std::end(kForceTerms),
                                     [&](const ForceTermEntry& e) { return e.name == name; });
    if (entry == std::end(kForceTerms)) {
      throw std::logic_error("membrane force term '" + std::string(name) + "' is not registered");
    }
    terms.push_back(entry->make(parameters, reference));
  }
  return terms;
}

std::vector<std::string> all_force_term_names() {
  std::vector<std::string> names;
  for (const auto& entry : kForceTerms) names.emplace_back(entry.name);
  return names;
}

}  // namespace rbcsim::membrane
