// Helfrich bending about the stress-free shape (force_terms.hpp, HelfrichTerm). Juelicher's
// discretisation (J. Phys. II France 6:1797, 1996), as surface_energies.hpp's HelfrichBending,
// with each vertex's reference mean curvature H0_v = M0_v / A0_v as its spontaneous curvature:
//   E = 2 kappa sum_v (H_v - H0_v)^2 A_v,  H_v = M_v / A_v,
//   M_v = (1/4) sum over v's edges of l_e theta_e,  A_v = (1/3) sum over v's triangles of A_t.
// With u_v = H_v - H0_v, the exact gradient is
//   dE/dM_v = 4 kappa u_v,  dE/dA_v = 2 kappa u_v (u_v - 2 H_v),
// carried to the positions through dM_v/dtheta_e = l_e / 4, dM_v/dl_e = theta_e / 4 (the hinge
// gradients of hinge.hpp) and dA_v/dA_t = 1/3 (the area gradients of area_term.cpp).
#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>

#include "membrane/force_terms.hpp"
#include "membrane/parallel.hpp"
#include "membrane/surface_energies.hpp"

namespace rbcsim::membrane {

HelfrichTerm::HelfrichTerm(const MembraneParameters& parameters, const ReferenceState& reference)
    : bending_modulus_pN_um_(parameters.k_bend_kBT * parameters.thermal_energy_pN_um) {
  if (reference.vertex_mean_curvatures_per_um.empty()) {
    throw std::invalid_argument(
        "membrane term 'helfrich': the reference state has no mean curvature per vertex");
  }
}

void HelfrichTerm::evaluate(const TermContext& context, TermScratch& scratch,
                            TermForces& out) const {
  const auto& topology = context.topology;
  const auto& geometry = context.geometry;
  const auto& reference_per_um = context.reference.vertex_mean_curvatures_per_um;
  const auto vertex_count = topology.vertex_count();
  const double kappa = bending_modulus_pN_um_;
  // Per vertex: u_v in deviations[v], dE/dA_v in deviations[V + v], the energy in energies[v]
  // (a closed mesh has 3V - 6 edges, so both fit).
  const auto departures_per_um = std::span(scratch.deviations).first(vertex_count);
  const auto area_loads_pN_per_um =
      std::span(scratch.deviations).subspan(vertex_count, vertex_count);
  const auto energies_pN_um = std::span(scratch.energies_pN_um).first(vertex_count);
  parallel_for(vertex_count, [&](std::size_t v) {
    const double area_um2 = vertex_area_um2(topology, geometry.triangle_area_vectors_um2, v);
    const double mean_curvature_per_um =
        integrated_mean_curvature_um(topology, geometry.edge_lengths_um,
                                     geometry.dihedral_angles_rad, v) /
        area_um2;
    const double departure = mean_curvature_per_um - reference_per_um[v];
    departures_per_um[v] = departure;
    area_loads_pN_per_um[v] = 2.0 * kappa * departure * (departure - 2.0 * mean_curvature_per_um);
    energies_pN_um[v] = 2.0 * kappa * departure * departure * area_um2;
  });
  double energy_pN_um = 0.0;
  double largest_departure = 0.0;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    energy_pN_um += energies_pN_um[v];
    largest_departure = std::max(largest_departure, std::abs(departures_per_um[v]));
  }
  out.energy_pN_um = energy_pN_um;
  out.max_abs_deviation = largest_departure;

  const auto& edges = topology.edges();
  parallel_for(edges.size(), [&](std::size_t e) {
    const double per_curvature_pN =
        kappa * (departures_per_um[edges[e].vertex0] + departures_per_um[edges[e].vertex1]);
    const HingeLoad load{0.0, per_curvature_pN * geometry.edge_lengths_um[e],
                         per_curvature_pN * geometry.dihedral_angles_rad[e]};
    distribute_as_gradient(hinge_of(context.positions_um, edges[e]), load,
                           std::span(scratch.slot_forces_pN).subspan(4 * e).first<4>());
  });
  context.stencils.hinge.gather(scratch.slot_forces_pN, out.forces_pN);

  parallel_for(context.triangles.size(), [&](std::size_t t) {
    const auto& corners = context.triangles[t];
    const double per_area_pN_per_um =
        (area_loads_pN_per_um[corners[0]] + area_loads_pN_per_um[corners[1]] +
         area_loads_pN_per_um[corners[2]]) /
        3.0;
    set_area_gradient_slots(context, t, -per_area_pN_per_um, scratch.slot_forces_pN);
  });
  context.stencils.triangle.add_gathered(scratch.slot_forces_pN, out.forces_pN);
}

}  // namespace rbcsim::membrane
