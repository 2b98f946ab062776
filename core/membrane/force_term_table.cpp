// The registry of membrane force terms (`membrane.forces`), in evaluation order.
#include <memory>

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

std::vector<std::string> all_force_term_names() {
  std::vector<std::string> names;
  for (const auto& entry : kForceTerms) names.emplace_back(entry.name);
  return names;
}

}  // namespace rbcsim::membrane
