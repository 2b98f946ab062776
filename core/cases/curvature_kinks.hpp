// The total-curvature term (paper Eqs. 11, 14, 17, 18) sums |theta_j| over the edges, so the
// membrane energy has a kink wherever an edge is flat (theta_j = 0): the edge's force jumps by
// twice its sign-carrying part g_j when theta_j changes sign. A stretched discocyte has such
// edges at equilibrium (the term pushes |theta| to zero and holds it there, like an L1 penalty,
// over whole flattened bands), so no shape makes every vertex force vanish: the net force keeps
// jumping by |2 g_j| (0.05-2 pN) and a minimiser chatters instead of converging (measured: FIRE
// and Euler both stall at 0.02-0.3 pN residuals on the N = 3 and N = 4 discocytes).
//
// The quasi-static stretch therefore finds the equilibrium of the model with |theta| smoothed
// over a width eps (Huber): |theta| -> theta^2 / (2 eps) + eps / 2 for |theta| < eps, unchanged
// outside. Its force is the model's with sign(theta_j) replaced by theta_j / eps on the flat
// edges: continuous, so the equilibrium is an ordinary one that FIRE converges to and a force
// tolerance certifies. The non-smooth equilibrium is its limit eps -> 0; a flat edge then sits
// within eps of flat instead of exactly flat (a vertex offset of eps times the wing height,
// 2.5e-3 um at eps = 1e-2 rad and the paper's 0.25 um edges).
//
// g_j is the part of the term's edge load that carries sign(theta_j) (docs/physics.md,
// "The three distributions"): with slope = slope(d_C) and scale = k_c kBT / L0,
//   `paper`:    F = -scale slope sign(theta_j), pushed as Eqs. 17-18;
//   `gradient`: dE/dtheta_j = (sqrt 3 / 2) scale slope l_j sign(theta_j);
// the part |theta_j| dE/dl_j is continuous at theta_j = 0 and stays as computed. A test checks
// g_j against the jump of the membrane model's own force across theta_j = 0.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/membrane_model.hpp"

namespace rbcsim::cases {

// The smoothing width eps, rad. Measured on the N = 4 discocyte (all six terms, the 13 Mills
// forces): the diameters differ by at most 0.0025 um between eps = 5e-3, 1e-2 and 2e-2 rad, while
// the whole curve takes 44 s, 16 s and 11 s (inside the window the force changes by |g_j| / eps
// per radian, which at 5e-3 starts to stiffen the relaxation).
inline constexpr double kCurvatureSmoothing_rad = 1e-2;

struct FlatEdge {
  std::array<std::int32_t, 4> vertices;  // vertex0, vertex1, wing0, wing1
  std::array<Vec3, 4> sign_force_pN;     // g_j: the force of the sign-carrying part for sign +1
  double angle_rad = 0.0;                // theta_j, |theta_j| < kCurvatureSmoothing_rad
};

class CurvatureKinks {
 public:
  // Active when the model's forces include total_curvature.
  explicit CurvatureKinks(const membrane::MembraneModel& model);

  bool active() const { return active_; }

  // The edges flatter than the smoothing width at positions_um, with their g_j; `forces` are
  // the model's forces there (for the cell's total-curvature deviation). Empty when not active.
  std::vector<FlatEdge> flat_edges(std::span<const Vec3> positions_um,
                                   const membrane::MembraneForces& forces) const;

  // Turns net_forces_pN (holding the model's forces at positions_um, plus any external ones)
  // into the forces of the smoothed model: on each flat edge, (theta_j / eps - sign theta_j) g_j
  // is added; in the vertex form (membrane/vertex_patch.hpp), on each flat patch
  // (|M_i| < eps_M), (M_i / eps_M - sign M_i) times the patch's pattern for a push of sign +1.
  // Unchanged when not active.
  void smooth(std::span<const Vec3> positions_um, const membrane::MembraneForces& forces,
              std::span<Vec3> net_forces_pN) const;

  // The vertex form's width for a patch offset M_i: eps L / 2 with L the mean reference edge
  // (a patch of edges L whose hinges are bent by theta has M ~ L theta / 2), um.
  double patch_smoothing_um() const { return patch_smoothing_um_; }

 private:
  void smooth_patches(std::span<const Vec3> positions_um, const membrane::MembraneForces& forces,
                      std::span<Vec3> net_forces_pN) const;
  // The term's push for sign +1 at the cell's total-curvature deviation, pN.
  double sign_push_pN(const membrane::MembraneForces& forces) const;

  const membrane::MembraneModel& model_;
  bool active_ = false;
  bool vertex_form_ = false;
  double patch_smoothing_um_ = 0.0;
};

}  // namespace rbcsim::cases
