#include "cases/fire_relaxation.hpp"

#include <stdexcept>

#include "cases/curvature_kinks.hpp"
#include "minimise/fire.hpp"

namespace rbcsim::cases {
namespace {

void check_arguments(const membrane::MembraneModel& model, std::span<Vec3> positions_um,
                     std::span<const Vec3> external_forces_pN,
                     const membrane::RelaxationSettings& settings) {
  const auto count = model.vertex_count();
  if (positions_um.size() != count ||
      (!external_forces_pN.empty() && external_forces_pN.size() != count)) {
    throw std::invalid_argument(
        "relax_membrane_fire: positions and external forces must have one entry per vertex");
  }
  if (settings.stiffness_update_interval == 0) {
    throw std::invalid_argument("relax_membrane_fire: needs stiffness_update_interval > 0");
  }
}

// The membrane under external forces as FIRE sees it: the net force of the smoothed model
// (curvature_kinks.hpp), shared within rigid groups.
class MembraneProblem final : public minimise::FireProblem {
 public:
  MembraneProblem(const membrane::MembraneModel& model, std::span<const Vec3> external_forces_pN,
                  const membrane::RelaxationSettings& settings)
      : model_(model),
        external_forces_pN_(external_forces_pN),
        settings_(settings),
        kinks_(model),
        workspace_(model.make_workspace()),
        forces_(model.make_forces()) {}

  void forces(std::span<const Vec3> positions_um, std::span<Vec3> net_pN) override {
    model_.compute(positions_um, workspace_, forces_, membrane::ForceDetail::totals);
    capped_vertex_count_ += forces_.capped_vertex_count;
    for (std::size_t i = 0; i < net_pN.size(); ++i) {
      net_pN[i] = forces_.total_pN[i] +
                  (external_forces_pN_.empty() ? Vec3::Zero() : Vec3(external_forces_pN_[i]));
    }
    kinks_.smooth(positions_um, forces_, net_pN);
    membrane::share_force_within_rigid_groups(settings_.rigid_groups, net_pN);
  }

  double stiffest_mode(std::span<const Vec3> positions_um) override {
    return membrane::estimate_stiffest_mode_pN_per_um(model_, positions_um);
  }

  std::size_t capped_vertex_count() const { return capped_vertex_count_; }

 private:
  const membrane::MembraneModel& model_;
  std::span<const Vec3> external_forces_pN_;
  const membrane::RelaxationSettings& settings_;
  const CurvatureKinks kinks_;
  membrane::MembraneWorkspace workspace_;
  membrane::MembraneForces forces_;
  std::size_t capped_vertex_count_ = 0;
};

}  // namespace

membrane::RelaxationResult relax_membrane_fire(const membrane::MembraneModel& model,
                                               std::span<Vec3> positions_um,
                                               std::span<const Vec3> external_forces_pN,
                                               const membrane::RelaxationSettings& settings) {
  check_arguments(model, positions_um, external_forces_pN, settings);
  MembraneProblem problem(model, external_forces_pN, settings);
  minimise::FireSettings fire_settings;
  fire_settings.force_tolerance = settings.force_tolerance_pN;
  fire_settings.max_iterations = settings.max_iterations;
  fire_settings.stiffness_update_interval = settings.stiffness_update_interval;
  const auto fire = minimise::minimise_fire(problem, positions_um, fire_settings);
  membrane::RelaxationResult result;
  result.converged = fire.converged;
  result.iterations = fire.iterations;
  result.simulated_time_s = fire.simulated_time;
  result.max_force_pN = fire.max_force;
  result.stiffest_mode_pN_per_um = fire.stiffest_mode;
  result.time_step_s = fire.time_step;
  result.capped_vertex_count = problem.capped_vertex_count();
  return result;
}

}  // namespace rbcsim::cases
