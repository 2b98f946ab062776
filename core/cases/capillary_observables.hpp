// The observables of the capillary experiment (paper §3.3-3.4; docs/physics.md), as pure
// functions of vertex positions and velocities (any one length unit throughout), and the transit
// of the cell's centroid through the narrow section.
//
// Flow along +x. The centroid is the mean vertex position, as CoupledSimulation's distance
// criterion uses. Deformation index (paper Eq. 19): DI = (extent in x) / (extent in y), the
// extents being max - min of the vertex coordinates: 1 for a discocyte released with its disc in
// the x-y plane, above 1 once the constriction squeezes it in y and stretches it along the flow.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "common/state_archive.hpp"
#include "common/vec3.hpp"

namespace rbcsim::cases {

Vec3 vertex_centroid(std::span<const Vec3> positions);
// max - min of each coordinate over the vertices.
Vec3 vertex_extents(std::span<const Vec3> positions);
// Eq. 19. Throws std::invalid_argument for a cell without extent in y.
double deformation_index(std::span<const Vec3> positions);
// Mean of the vertex velocities: the centroid's velocity when vertices move with x += u dt.
Vec3 mean_velocity(std::span<const Vec3> velocities);

// Reynolds number U D / nu of the inflow: mean inlet velocity, inlet diameter.
double reynolds_number(double mean_velocity_m_per_s, double diameter_um,
                       double kinematic_viscosity_m2_per_s);
// Capillary number mu U / G_s: viscous stress of the inflow against the membrane shear modulus.
double capillary_number(double mean_velocity_m_per_s, double dynamic_viscosity_Pa_s,
                        double shear_modulus_N_per_m);
// Small-strain shear modulus of the link term (Eq. 6) on a network of equilateral triangles of
// edge L0: the spring constant dF/dL = k kBT (1 + 1/tau^2) / (p L0) of Eq. 6 at d = 0, and
// mu = sqrt(3)/4 * spring constant for a harmonic triangular network (membrane_constants.csv).
double link_shear_modulus_N_per_m(double k_link_kBT, double tau_link, double thermal_energy_J,
                                  double persistence_length_um, double edge_length_um);

// When the centroid enters and leaves the narrow section [start_um, end_um] (along x): the times
// at which its x coordinate first reaches start_um and then end_um, linearly interpolated between
// two consecutive samples. Transit time = exit - entry. A centroid that moves back upstream after
// entering does not reset the entry: the transit is the time from first entry to first exit.
class NarrowSectionTransit {
 public:
  // Throws std::invalid_argument unless start_um < end_um.
  NarrowSectionTransit(double start_um, double end_um);

  // Samples in increasing time.
  void add_sample(double time_s, double centroid_x_um);

  std::optional<double> entry_time_s() const { return entry_time_s_; }
  std::optional<double> exit_time_s() const { return exit_time_s_; }
  std::optional<double> transit_time_s() const;
  bool passed() const { return exit_time_s_.has_value(); }
  double start_um() const { return start_um_; }
  double end_um() const { return end_um_; }

  // Checkpoints: the last sample and the crossings so far, as arrays named `<prefix>...`.
  void save_state(StateArchive& archive, const std::string& prefix) const;
  void restore_state(StateArchive& archive, const std::string& prefix);

 private:
  double start_um_;
  double end_um_;
  std::optional<double> previous_time_s_;
  double previous_x_um_ = 0.0;
  std::optional<double> entry_time_s_;
  std::optional<double> exit_time_s_;
};

}  // namespace rbcsim::cases
