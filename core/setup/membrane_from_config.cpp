#include "setup/membrane_from_config.hpp"

#include <array>
#include <cmath>
#include <utility>

namespace rbcsim::setup {
namespace {

constexpr double kPiconewtonMicrometresPerJoule = 1e18;

using Parameters = membrane::MembraneParameters;

// Options copied unchanged (same name and unit on both sides).
constexpr std::array<std::pair<const char*, double Parameters::*>, 18> kNumberOptions{{
    {"membrane.k_link_kBT", &Parameters::k_link_kBT},
    {"membrane.k_bend_kBT", &Parameters::k_bend_kBT},
    {"membrane.k_area_kBT", &Parameters::k_area_kBT},
    {"membrane.k_volume_kBT", &Parameters::k_volume_kBT},
    {"membrane.k_area_difference_kBT", &Parameters::k_area_difference_kBT},
    {"membrane.k_total_curvature_kBT", &Parameters::k_total_curvature_kBT},
    {"membrane.tau_link", &Parameters::tau_link},
    {"membrane.tau_bend_rad", &Parameters::tau_bend_rad},
    {"membrane.tau_area", &Parameters::tau_area},
    {"membrane.tau_volume", &Parameters::tau_volume},
    {"membrane.tau_area_difference", &Parameters::tau_area_difference},
    {"membrane.tau_total_curvature", &Parameters::tau_total_curvature},
    {"membrane.persistence_length_um", &Parameters::persistence_length_um},
    {"membrane.force_length_scale_um", &Parameters::force_length_scale_um},
    {"membrane.vertex_force_cap_pN", &Parameters::vertex_force_cap_pN},
    {"membrane.total_area_modulus_uN_per_m", &Parameters::total_area_modulus_uN_per_m},
    {"membrane.local_area_modulus_uN_per_m", &Parameters::local_area_modulus_uN_per_m},
    {"membrane.viscosity_Pa_s_um", &Parameters::viscosity_Pa_s_um},
}};

}  // namespace

membrane::MembraneParameters membrane_parameters_from(const config::Config& config) {
  Parameters parameters;
  for (const auto& [path, member] : kNumberOptions) parameters.*member = config.number(path);
  // The membrane works in pN and um: kBT from J to pN um.
  parameters.thermal_energy_pN_um =
      config.number("physics.thermal_energy_J") * kPiconewtonMicrometresPerJoule;
  parameters.forces = config.string_list("membrane.forces");
  parameters.distribution = config.string("membrane.distribution");
  parameters.kernel = config.string("membrane.kernel");
  parameters.viscosity_split = config.string("membrane.viscosity_split");
  parameters.viscosity_solve_tolerance = config.number("membrane.viscosity_solve_tolerance");
  return parameters;
}

double network_stiffness_scale(const config::Config& config, std::size_t triangle_count) {
  const auto calibrated =
      static_cast<double>(config.integer("membrane.network_calibrated_triangle_count"));
  if (calibrated == 0.0 || triangle_count == 0) return 1.0;
  // Mean edge length ~ sqrt(area / triangle count) for meshes of the same cell.
  return std::sqrt(calibrated / static_cast<double>(triangle_count));
}

membrane::MembraneParameters cell_membrane_parameters_from(const config::Config& config,
                                                           const mesh::TriangleMesh& cell) {
  auto parameters = membrane_parameters_from(config);
  const double scale = network_stiffness_scale(config, cell.triangles.size());
  parameters.k_link_kBT *= scale;
  parameters.k_area_kBT *= scale;
  return parameters;
}

}  // namespace rbcsim::setup
