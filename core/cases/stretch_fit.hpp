// The stretch fit of `rbcsim calibrate` (fit name "stretch"): the link stiffness k_link that puts
// the quasi-static optical-tweezers curve (quasi_static_stretch.hpp) closest to measured
// diameters, Mills et al. (2004) by default. This is how the membrane's shear modulus is measured
// in the first place (Mills et al., Dao et al. 2003 and Fedosov et al. 2010 fit mu to this
// curve); the patch tests (hexagonal_patch.hpp) then say which mu the fitted k_link is.
//
// Closest means the smallest misfit: the squared deviations of both diameters at every reference
// force, each in units of its error bar's half on its side (StretchComparison::misfit), so every
// point is inside its bar when each term is under 1. Only k_link is fitted: the patch-test moduli
// are linear in k, and the stretch probes the shear modulus, which k_link sets (k_area, the
// area-compression term, adds little to mu). Every other parameter stays as given.
//
// Each evaluation is a whole stretch curve from the rest shape (at the reference forces: seconds
// to tens of seconds at the paper's resolution); the search (common/scalar_minimum.hpp) runs in
// ln k_link, as the stiffness is a scale. A curve that fails (a force law's limit, no convergence)
// counts as an infinite misfit, which only bounds the search; so does one that needs more than
// max_iterations_per_force at a force.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "cases/stretch_case.hpp"
#include "cases/stretch_reference.hpp"
#include "membrane/parameters.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::cases {

struct StretchFitEvaluation {
  double k_link_kBT = 0.0;
  double misfit = 0.0;  // +infinity when the curve failed
  StretchComparison comparison;
  std::string failure;  // why the curve failed; empty when it did not
  double wall_time_s = 0.0;
};

struct StretchFitSettings {
  // The stretch's forces, contact and relaxation; its mode is the fit's: quasi-static. Reference
  // forces between forces run are interpolated (stretch_reference.hpp).
  StretchSettings stretch;
  std::vector<StretchReferencePoint> reference;
  double relative_tolerance = 1e-2;  // on k_link
  double first_step_factor = 1.5;    // the search's first trial is k_link times this
  // Relaxation iterations per force of a fit's curve, in place of the stretch's own budget: a
  // curve past the softest k_link that carries Mills' forces runs away at the last force and
  // fails only when the budget runs out, while the converging curves next to that limit need a
  // few times fewer (docs/validation.md, "The stretch fit"); a smaller budget ends the failing
  // ones sooner.
  std::size_t max_iterations_per_force = 20000;
  int max_evaluations = 30;
  // Called after every curve, for progress (a fit at the paper's resolution takes minutes).
  std::function<void(const StretchFitEvaluation&)> on_evaluation;
};

struct StretchFit {
  double start_k_link_kBT = 0.0;
  StretchFitEvaluation best;                      // the fitted k_link and its curve's comparison
  std::vector<StretchFitEvaluation> evaluations;  // in the order run
};

// Throws InputError (stretch.forces_pN) when no non-zero reference force lies within the forces;
// RuntimeFailure when the misfit has no minimum within max_evaluations (it still falls, or no
// curve could be computed), naming the k_link tried; Interrupted on a signal.
StretchFit fit_stretch_k_link(const mesh::TriangleMesh& cell,
                              const membrane::MembraneParameters& parameters,
                              const StretchFitSettings& settings);

}  // namespace rbcsim::cases
