// The total-curvature term (paper Eqs. 11, 14, 17, 18) sums |theta_j| over the edges, so the
// membrane energy has a kink wherever an edge is flat (theta_j = 0): the edge's force jumps by
// twice its sign-carrying part g_j when theta_j changes sign. A stretched discocyte has such
// edges at equilibrium (the term pushes |theta| to zero and holds it there, like an L1 penalty,
// over whole flattened bands), so no shape makes every vertex force vanish: the net force keeps
// jumping by |2 g_j| (0.05-0.3 pN) and a minimiser chatters instead of converging (measured:
// FIRE and Euler both stall at 0.02-0.3 pN residuals on the N = 3 and N = 4 discocytes).
//
// Equilibrium of a non-smooth energy means zero is in its subdifferential; "almost" equilibrium,
// the usual stopping rule of non-smooth minimisation, means zero is in its eps-subdifferential.
// For |theta| that is the set of weights t with |theta| - t theta <= eps, i.e. for theta > 0
// t in [max(-1, 1 - eps/theta), 1] (mirrored for theta < 0, all of [-1, 1] at theta = 0): the
// weight sign(theta_j) of g_j may move by up to eps/|theta_j|, continuously in theta (a sharp
// window would only move the kink to its edge). to_minimal_force chooses the weights that make
// the net force smallest (box-constrained least squares over the edges, projected Gauss-Seidel):
// the minimal-norm element of the eps-subdifferential. Driving the relaxation with it removes the
// chatter, and its size is the convergence measure. An accepted shape is an equilibrium of a
// total-curvature energy that differs from the exact one by at most eps per unit of each edge's
// |theta| coefficient.
//
// g_j is the part of the term's edge load that carries sign(theta_j) (the membrane README,
// "Angle terms"): with slope = slope(d_C) and scale = k_c kBT / L0,
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

// eps of the eps-subdifferential, rad. Measured on the N = 4 discocyte (all six terms, 31 and
// 68 pN, tolerance 1e-4 pN): the diameters differ by <= 0.002 um between eps = 1e-2 and 1e-3,
// while the relaxation needs 500-700 iterations at 1e-2 and does not converge in 30000 at 1e-3
// (the weight interval changes over |theta| ~ eps, so a small eps makes the force field stiff).
inline constexpr double kCurvatureSlack_rad = 1e-2;

struct KinkEdge {
  std::array<std::int32_t, 4> vertices;  // vertex0, vertex1, wing0, wing1
  std::array<Vec3, 4> sign_force_pN;     // g_j: the force of the sign-carrying part for sign +1
  double weight = 0.0;                   // of g_j: sign(theta_j), as in the model's force
  double lowest_weight = 0.0;            // the eps-subdifferential interval of the weight
  double highest_weight = 0.0;
};

class CurvatureKinks {
 public:
  // Active when the model's forces include total_curvature.
  explicit CurvatureKinks(const membrane::MembraneModel& model);

  bool active() const { return active_; }

  // Every edge with its g_j and weight interval at positions_um; `forces` are the model's forces
  // there (for the cell's total-curvature deviation). Empty when not active.
  std::vector<KinkEdge> kink_edges(std::span<const Vec3> positions_um,
                                   const membrane::MembraneForces& forces) const;

  // Turns net_forces_pN (membrane + external at positions_um) into the minimal-norm element of
  // the eps-subdifferential. Unchanged when not active. The weights found are kept as the start
  // of the next call (a relaxation calls it at nearby shapes, so a sweep or two then suffices).
  void to_minimal_force(std::span<const Vec3> positions_um, const membrane::MembraneForces& forces,
                        std::span<Vec3> net_forces_pN);

 private:
  const membrane::MembraneModel& model_;
  bool active_ = false;
  std::vector<double> previous_weights_;  // per edge; empty before the first call
};

}  // namespace rbcsim::cases
