#include "membrane/membrane_forces.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rbcsim::membrane {

double MembraneForces::total_energy_pN_um() const {
  double energy = 0.0;
  for (const auto& term : terms) energy += term.energy_pN_um;
  return energy;
}

const TermForces& MembraneForces::term(std::string_view name) const {
  for (const auto& term : terms) {
    if (term.name == name) return term;
  }
  throw std::out_of_range("membrane force term '" + std::string(name) + "' is not enabled");
}

CellDeviations cell_deviations(const ReferenceState& reference, double volume_um3, double area_um2,
                               double signed_curvature_sum_um, double absolute_curvature_sum_um) {
  return {(volume_um3 - reference.volume_um3) / reference.volume_um3,
          (area_um2 - reference.area_um2) / reference.area_um2,
          (signed_curvature_sum_um - reference.signed_curvature_sum_um) /
              std::abs(reference.signed_curvature_sum_um),
          (absolute_curvature_sum_um - reference.absolute_curvature_sum_um) /
              reference.absolute_curvature_sum_um};
}

void prepare_term_arrays(MembraneForces& forces, std::size_t vertex_count) {
  for (auto& term : forces.terms) term.forces_pN.resize(vertex_count);
}

void drop_term_detail(MembraneForces& forces) {
  for (auto& term : forces.terms) {
    term.forces_pN.clear();
    term.energy_pN_um = std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace rbcsim::membrane
