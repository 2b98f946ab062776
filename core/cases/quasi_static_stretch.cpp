#include "cases/quasi_static_stretch.hpp"

#include <string>

#include "cases/relaxation_methods.hpp"
#include "cases/stretch_geometry.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/wall_clock.hpp"

namespace rbcsim::cases {
namespace {

std::string at_force(double force_pN) { return "F = " + format_number(force_pN) + " pN: "; }

std::string not_converged(const StretchPoint& point, const membrane::RelaxationSettings& settings) {
  return at_force(point.force_pN) + "not converged after " + std::to_string(point.iterations) +
         " iterations (largest net vertex force " + format_number(point.residual_force_pN) +
         " pN, tolerance " + format_number(settings.force_tolerance_pN) +
         " pN); raise stretch.quasi_static.max_iterations";
}

std::string capped_at_equilibrium(double force_pN, std::size_t vertices, double cap_pN) {
  return at_force(force_pN) + "the vertex force cap of " + format_number(cap_pN) + " pN holds at " +
         std::to_string(vertices) +
         " vertices of the equilibrium, which is therefore the cap's, not the membrane's; spread "
         "the force over more vertices (stretch.contact.*) or raise membrane.vertex_force_cap_pN";
}

}  // namespace

StretchRun run_quasi_static_stretch(const membrane::MembraneModel& model, const StretchCell& cell,
                                    const StretchSettings& settings,
                                    const StretchObserver& observer) {
  const auto relax = find_relaxation_method(settings.relaxation);
  auto relaxation_settings = settings.relaxation_settings;
  relaxation_settings.rigid_groups = rigid_contact_groups(cell.patches, settings.contact);
  auto positions_um = cell.mesh.positions_um;
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  StretchRun run;
  for (const double force_pN : settings.forces_pN) {
    const auto external_pN = tweezer_forces_pN(model.vertex_count(), cell.patches, force_pN);
    StretchPoint point{.force_pN = force_pN};
    const auto start = WallClock::now();
    bool forces_known = false;
    try {
      const auto result = relax(model, positions_um, external_pN, relaxation_settings);
      point.converged = result.converged;
      point.iterations = result.iterations;
      point.residual_force_pN = result.max_force_pN;
      point.force_cap_hits = result.capped_vertex_count;
      if (!point.converged) run.failure = not_converged(point, settings.relaxation_settings);
      model.compute(positions_um, workspace, forces);
      forces_known = true;
      if (point.converged && forces.capped_vertex_count > 0) {
        point.converged = false;
        run.failure = capped_at_equilibrium(force_pN, forces.capped_vertex_count,
                                            model.parameters().vertex_force_cap_pN);
      }
    } catch (const RuntimeFailure& failure) {
      run.failure = at_force(force_pN) + failure.what();
    } catch (const Interrupted& interrupted) {  // the unfinished force is not a point
      run.failure = at_force(force_pN) + interrupted.what();
      run.interrupted = true;
      break;
    }
    point.wall_time_s = seconds_since(start);
    point.axial_um = axial_diameter_um(positions_um);
    point.transverse_um = transverse_diameter_um(positions_um);
    run.points.push_back(point);
    if (observer) {
      observer({run.points.size() - 1, run.points.back(), positions_um,
                forces_known ? &forces : nullptr, external_pN});
    }
    if (!run.ok()) break;
  }
  return run;
}

}  // namespace rbcsim::cases
