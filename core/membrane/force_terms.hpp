// The six membrane force terms (paper Eqs. 6-18) and their registry. Each term is a class whose
// evaluate() adds nothing to other terms' arrays; MembraneModel sums them. Every term's force
// magnitude follows the shared law F = -(k kBT / length) slope(d) (force_law.hpp), with length = p
// for the link and L0 (force_length_scale_um) for the others. Terms read the reference (L0,
// theta0, A0, V0, ...) from TermContext::reference.
//
// Adding a term: a .cpp with its class (declared here) and one row in force_term_table.cpp.
#pragma once

#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "common/registry.hpp"
#include "membrane/edge_friction.hpp"
#include "membrane/force_law.hpp"
#include "membrane/force_term.hpp"
#include "membrane/hinge.hpp"
#include "membrane/parameters.hpp"
#include "membrane/reference_state.hpp"

namespace rbcsim::membrane {

// What every term has: its force law and the scale k kBT / length of Eqs. 6-11.
class LawTerm : public ForceTerm {
 protected:
  LawTerm(ForceLaw law, double k_kBT, double length_um, double thermal_energy_pN_um)
      : law_(law), force_scale_pN_(k_kBT * thermal_energy_pN_um / length_um) {}

  ForceLaw law_;
  double force_scale_pN_;
};

// Link (Eq. 6), per edge, d = (L - L0)/L0, length = p. Central: the same in both distributions.
class LinkTerm final : public LawTerm {
 public:
  explicit LinkTerm(const MembraneParameters& parameters);
  void evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const override;
};

// Local area (Eq. 8), per triangle, d = (A - A0)/A0. Central: the same in both distributions.
class AreaTerm final : public LawTerm {
 public:
  explicit AreaTerm(const MembraneParameters& parameters);
  void evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const override;
};

// Volume (Eq. 9, no linear term), per cell, d = (V - V0)/V0. Central in both distributions.
class VolumeTerm final : public LawTerm {
 public:
  explicit VolumeTerm(const MembraneParameters& parameters);
  void evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const override;
};

// Whole-membrane area (not in the paper; Fedosov et al. 2010's global area term, Mirheo's ka_tot):
// per cell, d = (A - A0)/A0 and E = K A0 d^2 / 2 with K the total-area modulus, so
// F_i = -K d dA/dx_i. The lipid bilayer's area incompressibility, beside the skeleton's local
// area term. Harmonic: no limit tau (other terms fail first); NaN still fails.
class TotalAreaTerm final : public ForceTerm {
 public:
  TotalAreaTerm(const MembraneParameters& parameters, const ReferenceState& reference);
  void evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const override;

 private:
  double modulus_pN_per_um_;
  double reference_area_um2_;
};

// The total_area term's failure (both kernels): RuntimeFailure for a non-finite deviation.
[[noreturn]] void fail_non_finite_total_area(double deviation);

// The bilayer's local area (not in the paper; Fedosov et al. 2010's local area energy, Mirheo's
// ka): per triangle, d = (A - A0)/A0 and E_t = K A0 d^2 / 2 with K the local-area modulus, so
// F_k = -K d dA/dx_k. Beside the paper's skeleton term (Eq. 8, soft until its limit tau_a), the
// bilayer's resistance to a local change of area. Harmonic: no limit; NaN still fails. Not fused:
// the optimised kernel runs this class beside its fused terms.
class LocalAreaTerm final : public ForceTerm {
 public:
  explicit LocalAreaTerm(const MembraneParameters& parameters);
  void evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const override;

 private:
  double modulus_pN_per_um_;
};

// Membrane viscosity (not in the paper; Fedosov et al. 2010): friction on every edge from the
// relative velocity of its vertices (edge_friction.hpp), eta_m = viscosity_Pa_s_um shared by
// viscosity_split. Dissipative: its forces depend on TermContext::velocities_um_per_s (none at
// rest), it has no energy (energy_pN_um is 0) and no limit, and MembraneModel adds it after the
// force cap of the elastic terms.
class ViscosityTerm final : public ForceTerm {
 public:
  explicit ViscosityTerm(const MembraneParameters& parameters);
  void evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const override;

 private:
  EdgeFrictionParameters friction_;
};

// Helfrich bending about the stress-free shape (not in the paper; helfrich_term.cpp): Juelicher's
// E = 2 kappa sum_v (H_v - H0_v)^2 A_v with kappa = k_bend kBT (Table 2's 50 kBT is 2.05e-19 J,
// the bending modulus of Evans 1983 and Lim et al. 2002), H0_v the reference shape's mean
// curvature. The paper's bending (Eq. 7) without its limit tau_bend: a harmonic energy in the
// curvature, so a fold costs energy but never stops the run. Exact gradient, central; reads no
// distribution. Vertex-based and not fused: the optimised kernel runs this class beside its
// fused terms.
class HelfrichTerm final : public ForceTerm {
 public:
  // Throws std::invalid_argument for a reference without vertex_mean_curvatures_per_um.
  HelfrichTerm(const MembraneParameters& parameters, const ReferenceState& reference);
  void evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const override;

 private:
  double bending_modulus_pN_um_;  // kappa
};

// Common loop of the three angle-based terms (length L0): per edge, the term's HingeLoad is
// handed to the chosen distribution, which writes the hinge's four slots.
class HingeTerm : public LawTerm {
 public:
  void evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const final;

 protected:
  HingeTerm(ForceLaw law, double k_kBT, const MembraneParameters& parameters,
            HingeDistribution distribution)
      : LawTerm(law, k_kBT, parameters.force_length_scale_um, parameters.thermal_energy_pN_um),
        distribute_(distribution) {}

 private:
  // Deviations of the current shape, limit check, energy and max |d| (into scratch and out).
  virtual void measure(const TermContext& context, TermScratch& scratch, TermForces& out) const = 0;
  virtual HingeLoad edge_load(const TermContext& context, const TermScratch& scratch,
                              std::size_t edge) const = 0;

  HingeDistribution distribute_;
};

// Bending (Eq. 7), per edge, d = theta - theta0 (rad).
class BendingTerm final : public HingeTerm {
 public:
  BendingTerm(const MembraneParameters& parameters, HingeDistribution distribution);
  // The load of an edge whose angle deviates by d from its reference.
  HingeLoad load_for_deviation(double deviation_rad) const;

 private:
  void measure(const TermContext& context, TermScratch& scratch, TermForces& out) const override;
  HingeLoad edge_load(const TermContext& context, const TermScratch& scratch,
                      std::size_t edge) const override;

  double gradient_scale_pN_um_;  // K_b of the energy, see bending_term.cpp
};

// Area difference (Eqs. 10, 12, 13, 15, 16) and total curvature (Eqs. 11, 14, 17, 18): per cell,
// d = (S - S0)/|S0| with S = sum_j l_j w(theta_j) / 2, where w(theta) = theta for the area
// difference (S = DeltaA / 2 D0) and |theta| for the total curvature (S = C / 2 D0).
class CurvatureSumTerm final : public HingeTerm {
 public:
  enum class Measure { signed_curvature, absolute_curvature };
  CurvatureSumTerm(std::string_view name, Measure measure, double k_kBT, double tau,
                   const MembraneParameters& parameters, HingeDistribution distribution);

 private:
  void measure(const TermContext& context, TermScratch& scratch, TermForces& out) const override;
  HingeLoad edge_load(const TermContext& context, const TermScratch& scratch,
                      std::size_t edge) const override;
  std::string_view name_;
  Measure measure_;
  double gradient_scale_pN_;  // K / |S0| of the energy, see curvature_sum_term.cpp
};

// The per-vertex form of the three angle terms (`membrane.distribution = vertex`,
// vertex_patch.hpp): every vertex gets a push along its patch normal, shared out over its ring.
class VertexPatchTerm : public LawTerm {
 public:
  void evaluate(const TermContext& context, TermScratch& scratch, TermForces& out) const final;

 protected:
  VertexPatchTerm(ForceLaw law, double k_kBT, const MembraneParameters& parameters)
      : LawTerm(law, k_kBT, parameters.force_length_scale_um, parameters.thermal_energy_pN_um) {}

 private:
  // Scratch layout: the patch offsets M_i in deviations[0, V), the normals in
  // slot_forces_pN[0, V); a term may use deviations[V, 2V) and energies_pN_um[0, V) (the edge
  // count, their size, is 3V - 6 >= 2V), and evaluate() then writes the pushes over
  // energies_pN_um[0, V). Checks the limit, fills energy and max |d|.
  virtual void measure(const TermContext& context, TermScratch& scratch, TermForces& out) const = 0;
  // The push of `vertex` (of vertex_count), pN.
  virtual double push_pN(const TermScratch& scratch, std::size_t vertex_count,
                         std::size_t vertex) const = 0;
};

// HemoCell 2.x's per-vertex bending: d_i = (M_i - M0_i) / L (L the mean reference edge), push
// -(k_b kBT / L0) slope(d_i) with HemoCell's limit tau = sqrt(1/2) (its "0.5 - dDev^2"), not
// tau_bend (an angle). Energy K sum energy(d_i) with K = (k_b kBT / L0) L, so push = -dE/dM_i.
class VertexBendingTerm final : public VertexPatchTerm {
 public:
  VertexBendingTerm(const MembraneParameters& parameters, const ReferenceState& reference);
  static constexpr double kTau = 0.70710678118654752;  // sqrt(0.5)

 private:
  void measure(const TermContext& context, TermScratch& scratch, TermForces& out) const override;
  double push_pN(const TermScratch& scratch, std::size_t vertex_count,
                 std::size_t vertex) const override;

  double mean_edge_um_;
};

// The area difference and total curvature in the per-vertex form: the cell's d as in the edge
// forms (Eqs. 12-14), every vertex pushed with the paper's scalar F = -(k kBT / L0) slope(d)
// times w'(M_i): 1 for the area difference, sign(M_i) for the total curvature.
class VertexCurvatureSumTerm final : public VertexPatchTerm {
 public:
  VertexCurvatureSumTerm(std::string_view name, CurvatureSumTerm::Measure measure, double k_kBT,
                         double tau, const MembraneParameters& parameters);

 private:
  void measure(const TermContext& context, TermScratch& scratch, TermForces& out) const override;
  double push_pN(const TermScratch& scratch, std::size_t vertex_count,
                 std::size_t vertex) const override;

  std::string_view name_;
  CurvatureSumTerm::Measure measure_;
};

// d = (S - S0)/|S0| of a curvature sum for `measure`, checked against the law's limit (both
// forms); its energy K energy(d) with K = sqrt(3) (k kBT / L0) |S0| and |d| go into out.
double measure_curvature_sum(std::string_view name, CurvatureSumTerm::Measure measure,
                             const ForceLaw& law, double force_scale_pN,
                             const TermContext& context, TermForces& out);

// Factories of the area difference (guards |DeltaA0| near zero) and total curvature terms.
std::unique_ptr<ForceTerm> make_area_difference_term(const MembraneParameters& parameters,
                                                     const ReferenceState& reference);
std::unique_ptr<ForceTerm> make_total_curvature_term(const MembraneParameters& parameters,
                                                     const ReferenceState& reference);

// The registry, in evaluation order. Factories throw InputError for parameters or a reference the
// term cannot work with.
struct ForceTermEntry {
  std::string_view name;
  std::unique_ptr<ForceTerm> (*make)(const MembraneParameters& parameters,
                                     const ReferenceState& reference);
  // A dissipative term (its force depends on the vertex velocities, it has no energy): evaluated
  // by MembraneModel after the kernel and added to the total after the force cap, whatever the
  // kernel. Registered after every elastic term.
  bool dissipative = false;
};
// The registry (common/registry.hpp): the six terms above, and any a program or a test adds
// (docs/architecture.md, "Adding a force term"). force_term_table() is its entries.
Registry<ForceTermEntry>& force_term_registry();
std::span<const ForceTermEntry> force_term_table();
// The terms of `names` (registered names, in the order given), made by their factories.
std::vector<std::unique_ptr<ForceTerm>> make_force_terms(std::span<const std::string_view> names,
                                                         const MembraneParameters& parameters,
                                                         const ReferenceState& reference);

}  // namespace rbcsim::membrane
