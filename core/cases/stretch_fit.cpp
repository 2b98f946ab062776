#include "cases/stretch_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/scalar_minimum.hpp"
#include "common/wall_clock.hpp"

namespace rbcsim::cases {
namespace {

StretchSettings quasi_static(const StretchFitSettings& settings) {
  auto stretch = settings.stretch;
  stretch.mode = "quasi-static";
  stretch.relaxation_settings.max_iterations = settings.max_iterations_per_force;
  return stretch;
}

// The misfit is 0 for any k_link unless a loaded reference force lies within the forces run
// (compare_with_reference never extrapolates): refuse such a fit before running anything.
void require_loaded_reference_force(const StretchFitSettings& settings) {
  const auto& forces = settings.stretch.forces_pN;
  const auto spanned = [&forces](const StretchReferencePoint& point) {
    const auto [lowest, highest] = std::minmax_element(forces.begin(), forces.end());
    return point.force_pN > 0.0 && *lowest <= point.force_pN && point.force_pN <= *highest;
  };
  if (forces.empty() ||
      std::none_of(settings.reference.begin(), settings.reference.end(), spanned)) {
    throw InputError("stretch.forces_pN",
                     "the stretch fit needs forces that span at least one non-zero reference force "
                     "(Mills et al. 2004: 16 to 193 pN)");
  }
}

StretchFitEvaluation evaluate(const StretchCell& cell, membrane::MembraneParameters parameters,
                              const StretchSettings& stretch, const StretchFitSettings& settings) {
  const auto start = WallClock::now();
  const membrane::MembraneModel model(cell.mesh, parameters);
  const auto run = run_stretch(model, cell, stretch, {});
  if (run.interrupted) throw Interrupted("calibrate, stretch fit: " + run.failure);
  StretchFitEvaluation evaluation;
  evaluation.k_link_kBT = parameters.k_link_kBT;
  evaluation.comparison = compare_with_reference(run.points, settings.reference);
  evaluation.misfit =
      run.ok() ? evaluation.comparison.misfit : std::numeric_limits<double>::infinity();
  evaluation.failure = run.failure;
  evaluation.wall_time_s = seconds_since(start);
  return evaluation;
}

std::string tried(const std::vector<StretchFitEvaluation>& evaluations) {
  std::string text;
  for (const auto& evaluation : evaluations) {
    text += (text.empty() ? "" : ", ") + format_significant(evaluation.k_link_kBT) + " (" +
            (evaluation.failure.empty() ? format_significant(evaluation.misfit) : "failed") + ")";
  }
  return text;
}

}  // namespace

StretchFit fit_stretch_k_link(const mesh::TriangleMesh& cell,
                              const membrane::MembraneParameters& parameters,
                              const StretchFitSettings& settings) {
  require_loaded_reference_force(settings);
  const auto stretch_cell = prepare_stretch_cell(cell, settings.stretch.contact);
  const auto stretch = quasi_static(settings);
  StretchFit fit;
  fit.start_k_link_kBT = parameters.k_link_kBT;
  const auto misfit_at_log_k = [&](double log_k_link) {
    auto trial = parameters;
    trial.k_link_kBT = std::exp(log_k_link);
    fit.evaluations.push_back(evaluate(stretch_cell, trial, stretch, settings));
    if (settings.on_evaluation) settings.on_evaluation(fit.evaluations.back());
    return fit.evaluations.back().misfit;
  };
  const auto minimum = find_scalar_minimum(misfit_at_log_k, std::log(parameters.k_link_kBT),
                                           {.initial_step = std::log(settings.first_step_factor),
                                            .tolerance = std::log1p(settings.relative_tolerance),
                                            .max_evaluations = settings.max_evaluations});
  if (!minimum.converged) {
    throw RuntimeFailure("calibrate, stretch fit: no minimum of the misfit to within a relative " +
                         format_number(settings.relative_tolerance) + " in k_link after " +
                         std::to_string(minimum.evaluations) +
                         " curves; k_link (misfit) tried: " + tried(fit.evaluations));
  }
  fit.best = *std::min_element(fit.evaluations.begin(), fit.evaluations.end(),
                               [](const auto& a, const auto& b) { return a.misfit < b.misfit; });
  return fit;
}

}  // namespace rbcsim::cases
