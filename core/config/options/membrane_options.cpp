#include "common/registry.hpp"
#include "config/options/option_areas.hpp"
#include "membrane/edge_friction.hpp"
#include "membrane/hinge.hpp"
#include "membrane/membrane_kernel.hpp"
#include "membrane/parameters.hpp"

namespace rbcsim::config {
namespace {

// The defaults come from the membrane module's parameter struct: one source of truth.
const membrane::MembraneParameters kMembraneDefaults{};

// Every force term has the form F = -(k kBT / length) d (1 + 1/(tau^2 - d^2)) (Eqs. 6-11):
// k is its stiffness in kBT, tau the limit of its relative deviation d.
void add_stiffnesses(OptionTable& table) {
  // Discocyte values of Table 2; share/config/<morphology>.json overrides them per morphology.
  table
      .add_number("membrane.k_link_kBT", "kBT", kMembraneDefaults.k_link_kBT,
                  "Link stiffness k_l (Eq. 6).")
      .at_least(0.0);
  table
      .add_integer("membrane.network_calibrated_triangle_count", "", 0,
                   "Triangle count of the mesh k_link and k_area are calibrated for, or 0. When "
                   "set (Table 2's are for the paper's 2562-vertex cell: 5120), the cells of "
                   "stretch, shear, capillary and suspensions scale both by their mesh's mean "
                   "edge length over the calibrated one, sqrt(this / their triangle count), "
                   "which keeps the calibrated shear and area moduli on a coarser or finer mesh, "
                   "each morphology its own k; 0 applies them to any mesh as given (calibrate "
                   "always fits the k of its own mesh).")
      .at_least(0.0);
  table
      .add_number("membrane.k_bend_kBT", "kBT", kMembraneDefaults.k_bend_kBT,
                  "Bending stiffness k_b (Eq. 7).")
      .at_least(0.0);
  table
      .add_number("membrane.k_area_kBT", "kBT", kMembraneDefaults.k_area_kBT,
                  "Local area stiffness k_a (Eq. 8).")
      .at_least(0.0);
  table
      .add_number("membrane.k_volume_kBT", "kBT", kMembraneDefaults.k_volume_kBT,
                  "Volume stiffness k_v (Eq. 9).")
      .at_least(0.0);
  table
      .add_number("membrane.k_area_difference_kBT", "kBT", kMembraneDefaults.k_area_difference_kBT,
                  "Area-difference stiffness k_ad (Eq. 10).")
      .at_least(0.0);
  table
      .add_number("membrane.k_total_curvature_kBT", "kBT", kMembraneDefaults.k_total_curvature_kBT,
                  "Total-curvature stiffness k_c (Eq. 11).")
      .at_least(0.0);
}

void add_limits(OptionTable& table) {
  table
      .add_number("membrane.tau_link", "", kMembraneDefaults.tau_link,
                  "Limit tau_l of the relative edge strain (Eq. 6).")
      .above(0.0);
  table
      .add_number("membrane.tau_bend_rad", "rad", kMembraneDefaults.tau_bend_rad,
                  "Limit tau_b of the dihedral angle change (Eq. 7), pi/6.")
      .above(0.0);
  table
      .add_number("membrane.tau_area", "", kMembraneDefaults.tau_area,
                  "Limit tau_a of the relative area change (Eq. 8).")
      .above(0.0);
  // Table 2 prints 0.01, but HemoCell stores tau squared and runs with tau_v = 0.1; 0.01 would
  // make a 1 % volume change infinitely stiff.
  table
      .add_number("membrane.tau_volume", "", kMembraneDefaults.tau_volume,
                  "Limit tau_v of the relative volume change (Eq. 9); Table 2 prints 0.01, which "
                  "is HemoCell's stored tau_v^2: HemoCell runs with tau_v = 0.1.")
      .above(0.0);
  table
      .add_number("membrane.tau_area_difference", "", kMembraneDefaults.tau_area_difference,
                  "Limit tau_ad of the relative area difference change (Eq. 10).")
      .above(0.0);
  table
      .add_number("membrane.tau_total_curvature", "", kMembraneDefaults.tau_total_curvature,
                  "Limit tau_tc of the relative total curvature change (Eq. 11).")
      .above(0.0);
  // Not in the paper: the bilayer's area incompressibility as a whole-membrane term (Fedosov et
  // al. 2010's global area energy; Mirheo's ka_tot). docs/physics.md derives the default.
  table
      .add_number("membrane.total_area_modulus_uN_per_m", "uN/m",
                  kMembraneDefaults.total_area_modulus_uN_per_m,
                  "Modulus K of the whole-membrane area term, E = K (A - A0)^2 / (2 A0); acts "
                  "only when membrane.forces names total_area (not one of the paper's six).")
      .at_least(0.0);
  // Not in the paper: the bilayer's local area incompressibility, per triangle (Fedosov et al.
  // 2010's local area energy; Mirheo's ka). docs/physics.md derives the default.
  table
      .add_number("membrane.local_area_modulus_uN_per_m", "uN/m",
                  kMembraneDefaults.local_area_modulus_uN_per_m,
                  "Modulus K of the per-triangle area term, E = sum_t K (A_t - A0_t)^2 / (2 A0_t); "
                  "acts only when membrane.forces names local_area (not one of the paper's six).")
      .at_least(0.0);
  // Not in the paper either: membrane viscosity as edge friction (Fedosov et al. 2010). The
  // default is Hochmuth & Hampel 1979's measured surface viscosity.
  table
      .add_number("membrane.viscosity_Pa_s_um", "Pa s um", kMembraneDefaults.viscosity_Pa_s_um,
                  "2D membrane viscosity eta_m of the viscosity term (1 Pa s um = 1e-6 N s/m; "
                  "Hochmuth & Hampel 1979: 0.5); acts only when membrane.forces names viscosity, "
                  "and 0 is no viscosity.")
      .at_least(0.0);
  table.add_choice(
      "membrane.viscosity_split", membrane::viscosity_splits().names(),
      kMembraneDefaults.viscosity_split,
      "How eta_m = sqrt3 gamma_T + sqrt3 gamma_C / 4 is shared by the edge friction: " +
          membrane::viscosity_splits().described_names() + ".");
  table
      .add_number("membrane.viscosity_solve_tolerance", "",
                  kMembraneDefaults.viscosity_solve_tolerance,
                  "The implicit step of the viscosity term in a coupled run is converged when its "
                  "residual is below this fraction of the residual at the fluid's velocities "
                  "(docs/performance.md: the iterations and the accuracy it buys).")
      .above(0.0)
      .below(1.0);
}

void add_scales_and_variants(OptionTable& table) {
  table
      .add_number("membrane.persistence_length_um", "um", kMembraneDefaults.persistence_length_um,
                  "Persistence length p, the length in the denominator of the link force (Eq. 6; "
                  "HemoCell's p = 7.5 nm).")
      .above(0.0);
  table
      .add_number("membrane.force_length_scale_um", "um", kMembraneDefaults.force_length_scale_um,
                  "L0 of Table 2, the length in the denominator of Eqs. 7-11.")
      .above(0.0);
  table.add_choice_list("membrane.forces", membrane::all_force_term_names(),
                        kMembraneDefaults.forces,
                        "Force terms switched on: the paper's six by default; total_area adds the "
                        "whole-membrane area term, viscosity the membrane viscosity, helfrich "
                        "Helfrich bending about the stress-free shape with kappa = k_bend kBT "
                        "(in place of bend, which has the limit tau_bend), local_area the "
                        "bilayer's per-triangle area.");
  table.add_choice("membrane.kernel", entry_names(membrane::membrane_kernel_table()),
                   kMembraneDefaults.kernel,
                   "Force kernel: the fused optimised one, or the plain reference it is tested "
                   "against (same forces to round-off).");
  table.add_choice("membrane.distribution", membrane::distribution_names(),
                   kMembraneDefaults.distribution,
                   "Distribution of the angle-based forces: exact energy gradient (conserves "
                   "angular momentum), Eqs. 15-18 as printed, or vertex (HemoCell 2.x's "
                   "per-vertex form; needs membrane.kernel=reference).");
  table
      .add_number("membrane.vertex_force_cap_pN", "pN", kMembraneDefaults.vertex_force_cap_pN,
                  "Per-vertex force cap: a safety net only, every trigger is reported.")
      .above(0.0);
}

}  // namespace

void add_membrane_options(OptionTable& table) {
  add_stiffnesses(table);
  add_limits(table);
  add_scales_and_variants(table);
}

}  // namespace rbcsim::config
