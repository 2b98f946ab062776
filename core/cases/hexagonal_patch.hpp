// The hexagonal patch test (paper §2.3 and Fig. 7; docs/physics.md): a centre node and
// its six neighbours at the edge length a, 12 links and 6 equilateral triangles, with the link
// (Eq. 6) and local-area (Eq. 8) terms of the membrane model. The six boundary nodes are moved by
// a small affine map x -> (I + eps G) x (uniaxial, pure shear, isotropic expansion); the stress is
// the virial of the loads that hold them, sigma = -(1/A0) sum_i x_i (x) F_i, central-differenced
// in eps, which gives the small-strain 2D moduli.
//
// Two readings of the same patch are reported:
//   network   the infinite triangulated sheet the patch stands for (a cell's membrane): each rim
//             link is shared with the neighbouring patch of the tiling, so it counts one half.
//             This is what a cell mesh has, and what membrane_constants.csv's relations describe.
//   isolated  the 7-node patch alone, every link whole, as HemoCell's material tester pulls it.
#pragma once

#include "membrane/parameters.hpp"

namespace rbcsim::cases {

// Small-strain moduli of a 2D membrane, uN/m (= pN/um): E_s (2D Young's), mu (shear), K (area
// compression), and the 2D Poisson ratio.
struct MembraneModuli {
  double young_uN_per_m = 0.0;
  double shear_uN_per_m = 0.0;
  double area_uN_per_m = 0.0;
  double poisson_ratio = 0.0;
};

// The moduli of an isotropic 2D solid from K and mu: E = 4 K mu / (K + mu), nu = (K - mu)/(K + mu).
MembraneModuli isotropic_moduli(double area_uN_per_m, double shear_uN_per_m);

// K and mu of each term of the network, per unit stiffness (k = 1 kBT): the moduli are linear in
// k_l and k_a in the small-strain limit, K = k_l K_link + k_a K_area (and the same for mu).
struct PatchStiffness {
  double link_shear_uN_per_m = 0.0;
  double link_area_uN_per_m = 0.0;
  double area_term_shear_uN_per_m = 0.0;
  double area_term_area_uN_per_m = 0.0;
};

struct HexagonalPatchMeasurement {
  // From the uniaxial stretch with free lateral contraction (E_s, nu), pure shear (mu) and
  // isotropic expansion (K): four independent measurements; isotropy makes them consistent.
  MembraneModuli network;
  MembraneModuli isolated;
  // The centre node is free; by the patch's point symmetry its equilibrium under an affine
  // boundary map is the affine position. The largest force left on it there (a check), pN.
  double largest_centre_force_pN = 0.0;
};

// `parameters` gives k_l, k_a, the limits tau, kBT, p, L0 and the kernel; its force list is
// replaced by {link, area}. edge_um: the patch's rest edge a; strain: the amplitude eps (small).
HexagonalPatchMeasurement measure_hexagonal_patch(const membrane::MembraneParameters& parameters,
                                                  double edge_um, double strain);

// The network's K and mu per term with k_l = k_a = 1 kBT, measured as above.
PatchStiffness measure_patch_stiffness(const membrane::MembraneParameters& parameters,
                                       double edge_um, double strain);

// The same in closed form (derived in docs/physics.md, "Calibration"): a link is a spring of
// stiffness k_s = (k_l kBT / p)(1 + 1/tau_l^2) / a, so mu = (sqrt 3 / 4) k_s and K_link = 2 mu; the
// area term's energy per triangle (k_a kBT / L0)(6 A0 / P0)(1 + 1/tau_a^2) d^2 / 2 over its area A0
// adds K_area = 2 k_a kBT (1 + 1/tau_a^2) / (L0 a) to K and nothing to mu.
PatchStiffness analytic_patch_stiffness(const membrane::MembraneParameters& parameters,
                                        double edge_um);

// K and mu of the network for stiffnesses k_link_kBT and k_area_kBT.
MembraneModuli network_moduli(const PatchStiffness& stiffness, double k_link_kBT,
                              double k_area_kBT);

}  // namespace rbcsim::cases
