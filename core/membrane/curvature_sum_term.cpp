// Area difference (Eqs. 10, 12, 13, 15, 16) and total curvature (Eqs. 11, 14, 17, 18).
// Per cell, S = sum_j l_j w(theta_j) / 2 with w(theta) = theta (S = DeltaA / 2 D0) or |theta|
// (S = C / 2 D0), and d = (S - S0)/|S0|. We divide by |S0| rather than S0: DeltaA0 can be negative
// (a cup-shaped stomatocyte), and d must grow when S grows for the force to restore S whatever
// the sign of S0. C0 is always positive.
//
// `paper`: every edge gets the cell's scalar F = -(k kBT / L0) slope(d), times w'(theta_j) (1 for
// the area difference; sign(theta_j) for the total curvature: C sums |M_j|, so restoring C means
// reducing |theta_j|), pushed as in Eqs. 15-18 (hinge.hpp).
// `gradient`: E = K energy(d), d a function of every l_j and theta_j:
//   dE/dtheta_j = K slope(d) l_j w'(theta_j) / (2 |S0|),  dE/dl_j = K slope(d) w(theta_j) / (2
//   |S0|).
// `vertex` (vertex_patch.hpp): every vertex pushed with F w'(M_i), M_i its patch offset.
// Scale of K, so that one element has the paper's stiffness: for an equilateral pair of edge L0
// (h = (sqrt(3)/2) L0, w' = 1) the gradient pushes a wing with
// dE/dtheta / h = K slope(d) / (sqrt(3) |S0|), the paper with (k kBT / L0) slope(d), so
//   K = sqrt(3) |S0| k kBT / L0.
#include <cmath>
#include <sstream>

#include "common/errors.hpp"
#include "membrane/force_terms.hpp"

namespace rbcsim::membrane {
namespace {

// Below this |DeltaA0| / C0, a change of the signed curvature by tau_ad * 1e-3 of the total
// curvature (0.15 % for tau_ad = 1.5) would already hit the singular limit: the term is unusable.
constexpr double kMinimumAreaDifferenceRatio = 1e-3;

}  // namespace

CurvatureSumTerm::CurvatureSumTerm(std::string_view name, Measure measure, double k_kBT, double tau,
                                   const MembraneParameters& parameters,
                                   HingeDistribution distribution)
    : HingeTerm(ForceLaw::with_linear_term(tau), k_kBT, parameters, distribution),
      name_(name),
      measure_(measure),
      gradient_scale_pN_(std::sqrt(3.0) * force_scale_pN_) {}

double measure_curvature_sum(std::string_view name, CurvatureSumTerm::Measure measure,
                             const ForceLaw& law, double force_scale_pN,
                             const TermContext& context, TermForces& out) {
  const bool absolute = measure == CurvatureSumTerm::Measure::absolute_curvature;
  const double current_um = absolute ? context.geometry.absolute_curvature_sum_um
                                     : context.geometry.signed_curvature_sum_um;
  const double reference_um = absolute ? context.reference.absolute_curvature_sum_um
                                        : context.reference.signed_curvature_sum_um;
  const double deviation = (current_um - reference_um) / std::abs(reference_um);
  require_within_limit(name, "the cell", deviation, law.tau());
  // K energy(d) with K = sqrt(3) (k kBT / L0) |S0|.
  out.energy_pN_um = std::sqrt(3.0) * force_scale_pN * std::abs(reference_um) * law.energy(deviation);
  out.max_abs_deviation = std::abs(deviation);
  return deviation;
}

void CurvatureSumTerm::measure(const TermContext& context, TermScratch& scratch,
                               TermForces& out) const {
  scratch.cell_deviation =
      measure_curvature_sum(name_, measure_, law_, force_scale_pN_, context, out);
}

HingeLoad CurvatureSumTerm::edge_load(const TermContext& context, const TermScratch& scratch,
                                      std::size_t edge) const {
  const double angle_rad = context.geometry.dihedral_angles_rad[edge];
  const bool absolute = measure_ == Measure::absolute_curvature;
  const double weight_rad = absolute ? std::abs(angle_rad) : angle_rad;
  const double weight_slope = absolute ? (angle_rad > 0.0) - (angle_rad < 0.0) : 1.0;
  const double slope = law_.slope(scratch.cell_deviation);
  // K / |S0| = gradient_scale: the reference sum cancels in the per-edge loads.
  const double half_gradient_pN = 0.5 * gradient_scale_pN_ * slope;
  return {-force_scale_pN_ * slope * weight_slope,
          half_gradient_pN * context.geometry.edge_lengths_um[edge] * weight_slope,
          half_gradient_pN * weight_rad};
}

VertexCurvatureSumTerm::VertexCurvatureSumTerm(std::string_view name,
                                               CurvatureSumTerm::Measure measure, double k_kBT,
                                               double tau, const MembraneParameters& parameters)
    : VertexPatchTerm(ForceLaw::with_linear_term(tau), k_kBT, parameters),
      name_(name),
      measure_(measure) {}

void VertexCurvatureSumTerm::measure(const TermContext& context, TermScratch& scratch,
                                     TermForces& out) const {
  scratch.cell_deviation =
      measure_curvature_sum(name_, measure_, law_, force_scale_pN_, context, out);
}

double VertexCurvatureSumTerm::push_pN(const TermScratch& scratch, std::size_t,
                                       std::size_t vertex) const {
  // w'(M_i): C sums |M|, so restoring it flattens convex and concave patches alike.
  const double offset_um = scratch.deviations[vertex];
  const double weight_slope = measure_ == CurvatureSumTerm::Measure::absolute_curvature
                                  ? (offset_um > 0.0) - (offset_um < 0.0)
                                  : 1.0;
  return -force_scale_pN_ * law_.slope(scratch.cell_deviation) * weight_slope;
}

std::unique_ptr<ForceTerm> make_area_difference_term(const MembraneParameters& parameters,
                                                     const ReferenceState& reference) {
  const double ratio =
      std::abs(reference.signed_curvature_sum_um) / reference.absolute_curvature_sum_um;
  if (!(ratio >= kMinimumAreaDifferenceRatio)) {
    std::ostringstream problem;
    problem << "the reference area difference DeltaA0 is near zero (|sum_j l_j theta_j / 2| = "
            << std::abs(reference.signed_curvature_sum_um) << " um, " << ratio
            << " of the total curvature sum), so d = (DeltaA - DeltaA0)/|DeltaA0| is undefined; "
               "remove \"area_difference\" from membrane.forces for this shape";
    throw InputError("stress-free mesh", problem.str());
  }
  if (is_vertex_distribution(parameters.distribution)) {
    return std::make_unique<VertexCurvatureSumTerm>(
        "area_difference", CurvatureSumTerm::Measure::signed_curvature,
        parameters.k_area_difference_kBT, parameters.tau_area_difference, parameters);
  }
  return std::make_unique<CurvatureSumTerm>(
      "area_difference", CurvatureSumTerm::Measure::signed_curvature,
      parameters.k_area_difference_kBT, parameters.tau_area_difference, parameters,
      find_hinge_distribution(parameters.distribution));
}

std::unique_ptr<ForceTerm> make_total_curvature_term(const MembraneParameters& parameters,
                                                     const ReferenceState&) {
  if (is_vertex_distribution(parameters.distribution)) {
    return std::make_unique<VertexCurvatureSumTerm>(
        "total_curvature", CurvatureSumTerm::Measure::absolute_curvature,
        parameters.k_total_curvature_kBT, parameters.tau_total_curvature, parameters);
  }
  return std::make_unique<CurvatureSumTerm>(
      "total_curvature", CurvatureSumTerm::Measure::absolute_curvature,
      parameters.k_total_curvature_kBT, parameters.tau_total_curvature, parameters,
      find_hinge_distribution(parameters.distribution));
}

}  // namespace rbcsim::membrane
