#include "shapes/shape_report.hpp"

#include <numbers>

#include "mesh/geometry.hpp"
#include "mesh/topology.hpp"
#include "shapes/shape_analysis.hpp"

namespace rbcsim::shapes {
nlohmann::ordered_json morphology_json(const mesh::TriangleMesh& mesh) {
  const auto spicules = find_spicules(mesh);
  const auto invagination = measure_invagination(mesh);
  const auto profile = distance_from_evans_fung(mesh);
  return {
      {"spicules",
       {{"count", spicules.tip_vertices.size()},
        {"mesh_spikes", spicules.spike_vertices.size()},
        {"nearest_spacing_mean_um", spicules.nearest_spacing_mean_um},
        {"nearest_spacing_cv", spicules.nearest_spacing_cv},
        {"mean_height_um", spicules.mean_height_um}}},
      {"invagination",
       {{"depth_um", invagination.depth_um},
        {"diameter_um", invagination.diameter_um},
        {"depth_to_diameter", invagination.depth_to_diameter},
        {"centre_thickness_um", invagination.centre_thickness_um},
        {"cup_offset_um", invagination.cup_offset_um}}},
      {"evans_fung_distance_um", {{"max", profile.max_um}, {"rms", profile.rms_um}}},
  };
}

nlohmann::ordered_json energy_json(const mesh::TriangleMesh& mesh, int subdivisions,
                                   const EnergyShapeSettings& settings) {
  const auto reference =
      oblate_spheroid(subdivisions, settings.skeleton_reference_reduced_volume, settings.area_um2);
  const auto topology = mesh::MeshTopology::build(mesh);
  const auto parameters = bilayer_couple_parameters(settings, mesh::surface_area_um2(mesh),
                                                    mesh::enclosed_volume_um3(mesh));
  const double kappa_pN_um = parameters.bending.bending_modulus_pN_um;
  BilayerCoupleModel model(
      mesh.triangles, topology,
      membrane::capture_skeleton_reference(reference.positions_um, reference.triangles),
      parameters);
  const auto energies = model.evaluate(mesh.positions_um, {});
  const double sphere = 8.0 * std::numbers::pi * kappa_pN_um;
  const double realised = membrane::reduced_area_difference(
      mesh::curvature_sums(mesh.positions_um, topology).signed_um, parameters.area_um2);
  return {
      {"relaxed_area_difference", settings.relaxed_area_difference},
      {"reduced_area_difference", realised},
      {"energy_pN_um",
       {{"bending", energies.bending_pN_um},
        {"area_difference", energies.area_difference_pN_um},
        {"skeleton", energies.skeleton_pN_um},
        {"total", energies.total_pN_um()}}},
      {"energy_per_8_pi_kappa",
       {{"bending", energies.bending_pN_um / sphere},
        {"area_difference", energies.area_difference_pN_um / sphere},
        {"skeleton", energies.skeleton_pN_um / sphere},
        {"total", energies.total_pN_um() / sphere}}},
  };
}

nlohmann::ordered_json minimisation_json(const EnergyShape& shape) {
  auto trials = nlohmann::ordered_json::array();
  double seconds = 0.0;
  for (const auto& trial : shape.trials) {
    nlohmann::ordered_json entry = {{"path", trial.path},
                                    {"seed", trial.seed},
                                    {"iterations", trial.iterations},
                                    {"converged", trial.converged},
                                    {"max_force_pN", trial.max_force_pN},
                                    {"self_intersections", trial.self_intersections},
                                    {"seconds", trial.seconds},
                                    {"energy_pN_um", trial.energies.total_pN_um()}};
    if (trial.failure) entry["failure"] = *trial.failure;
    trials.push_back(entry);
    seconds += trial.seconds;
  }
  return {{"best_trial", shape.best_trial}, {"seconds", seconds}, {"trials", trials}};
}

nlohmann::ordered_json redistribution_json(const Redistribution& redistribution) {
  return {{"sweeps", redistribution.sweeps},
          {"kept", redistribution.kept},
          {"outcome", redistribution.outcome},
          {"largest_restoring_move_um", redistribution.largest_restoring_move_um},
          {"angles_before_deg",
           {{"min", redistribution.min_angle_before_deg},
            {"max", redistribution.max_angle_before_deg}}},
          {"angles_deg",
           {{"min", redistribution.min_angle_deg}, {"max", redistribution.max_angle_deg}}}};
}

}  // namespace rbcsim::shapes
