// The registry of membrane force terms (`membrane.forces`), in evaluation order.
#include <memory>
#include <string>
#include <vector>

#include "membrane/force_terms.hpp"

namespace rbcsim::membrane {
namespace {

std::vector<ForceTermEntry> built_in_terms() {
  return {
      {"link",
       [](const MembraneParameters& p, const ReferenceState&) -> std::unique_ptr<ForceTerm> {
         return std::make_unique<LinkTerm>(p);
       }},
      {"bend",
       [](const MembraneParameters& p, const ReferenceState& r) -> std::unique_ptr<ForceTerm> {
         if (is_vertex_distribution(p.distribution)) {
           return std::make_unique<VertexBendingTerm>(p, r);
         }
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
      {"total_area",
       [](const MembraneParameters& p, const ReferenceState& r) -> std::unique_ptr<ForceTerm> {
         return std::make_unique<TotalAreaTerm>(p, r);
       }},
      {"helfrich",
       [](const MembraneParameters& p, const ReferenceState& r) -> std::unique_ptr<ForceTerm> {
         return std::make_unique<HelfrichTerm>(p, r);
       }},
      {"local_area",
       [](const MembraneParameters& p, const ReferenceState&) -> std::unique_ptr<ForceTerm> {
         return std::make_unique<LocalAreaTerm>(p);
       }},
      {"viscosity",
       [](const MembraneParameters& p, const ReferenceState&) -> std::unique_ptr<ForceTerm> {
         return std::make_unique<ViscosityTerm>(p);
       },
       true},
  };
}

}  // namespace

Registry<ForceTermEntry>& force_term_registry() {
  static Registry<ForceTermEntry> registry("force term", built_in_terms());
  return registry;
}

std::span<const ForceTermEntry> force_term_table() { return force_term_registry().entries(); }

std::vector<std::unique_ptr<ForceTerm>> make_force_terms(std::span<const std::string_view> names,
                                                         const MembraneParameters& parameters,
                                                         const ReferenceState& reference) {
  std::vector<std::unique_ptr<ForceTerm>> terms;
  for (auto name : names) {
    terms.push_back(
        force_term_registry().find(name, "membrane.forces").make(parameters, reference));
  }
  return terms;
}

std::vector<std::string> all_force_term_names() { return force_term_registry().names(); }

std::vector<std::string> elastic_force_term_names() {
  std::vector<std::string> names;
  for (const auto& entry : force_term_table()) {
    if (!entry.dissipative) names.emplace_back(entry.name);
  }
  return names;
}

std::vector<std::string> paper_force_term_names() {
  return {"link", "bend", "area", "volume", "area_difference", "total_curvature"};
}

}  // namespace rbcsim::membrane
