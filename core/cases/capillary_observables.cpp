#include "cases/capillary_observables.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace rbcsim::cases {
namespace {

constexpr double kMetresPerMicrometre = 1e-6;

// The time at which x crosses `level` between two samples, linearly interpolated.
double crossing_time_s(double time0_s, double x0_um, double time1_s, double x1_um, double level) {
  if (x1_um == x0_um) return time1_s;
  return time0_s + (time1_s - time0_s) * (level - x0_um) / (x1_um - x0_um);
}

}  // namespace

Vec3 vertex_centroid(std::span<const Vec3> positions) {
  Vec3 sum = Vec3::Zero();
  for (const auto& position : positions) sum += position;
  return sum / static_cast<double>(positions.size());
}

Vec3 vertex_extents(std::span<const Vec3> positions) {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 high = -low;
  for (const auto& position : positions) {
    low = low.cwiseMin(position);
    high = high.cwiseMax(position);
  }
  return high - low;
}

double deformation_index(std::span<const Vec3> positions) {
  const Vec3 extents = vertex_extents(positions);
  if (!(extents.y() > 0.0)) {
    throw std::invalid_argument("deformation index: the cell has no extent in y");
  }
  return extents.x() / extents.y();
}

Vec3 mean_velocity(std::span<const Vec3> velocities) { return vertex_centroid(velocities); }

double reynolds_number(double mean_velocity_m_per_s, double diameter_um,
                       double kinematic_viscosity_m2_per_s) {
  return mean_velocity_m_per_s * diameter_um * kMetresPerMicrometre / kinematic_viscosity_m2_per_s;
}

double capillary_number(double mean_velocity_m_per_s, double dynamic_viscosity_Pa_s,
                        double shear_modulus_N_per_m) {
  return dynamic_viscosity_Pa_s * mean_velocity_m_per_s / shear_modulus_N_per_m;
}

double link_shear_modulus_N_per_m(double k_link_kBT, double tau_link, double thermal_energy_J,
                                  double persistence_length_um, double edge_length_um) {
  const double spring_constant_N_per_m =
      k_link_kBT * thermal_energy_J * (1.0 + 1.0 / (tau_link * tau_link)) /
      (persistence_length_um * kMetresPerMicrometre * edge_length_um * kMetresPerMicrometre);
  return std::sqrt(3.0) / 4.0 * spring_constant_N_per_m;
}

NarrowSectionTransit::NarrowSectionTransit(double start_um, double end_um)
    : start_um_(start_um), end_um_(end_um) {
  if (!(start_um < end_um)) {
    throw std::invalid_argument("narrow section: start must lie upstream of end");
  }
}

void NarrowSectionTransit::add_sample(double time_s, double centroid_x_um) {
  const bool has_previous = previous_time_s_.has_value();
  const auto crossing = [&](double level) {
    return has_previous && previous_x_um_ < level
               ? crossing_time_s(*previous_time_s_, previous_x_um_, time_s, centroid_x_um, level)
               : time_s;
  };
  if (!entry_time_s_ && centroid_x_um >= start_um_) entry_time_s_ = crossing(start_um_);
  if (entry_time_s_ && !exit_time_s_ && centroid_x_um >= end_um_) {
    exit_time_s_ = crossing(end_um_);
  }
  previous_time_s_ = time_s;
  previous_x_um_ = centroid_x_um;
}

std::optional<double> NarrowSectionTransit::transit_time_s() const {
  if (!entry_time_s_ || !exit_time_s_) return std::nullopt;
  return *exit_time_s_ - *entry_time_s_;
}

namespace {

// An optional number as an array of zero or one element.
std::vector<double> optional_array(const std::optional<double>& value) {
  return value ? std::vector<double>{*value} : std::vector<double>{};
}

std::optional<double> optional_of(const std::vector<double>& array) {
  return array.empty() ? std::nullopt : std::optional<double>(array.front());
}

}  // namespace

void NarrowSectionTransit::save_state(StateArchive& archive, const std::string& prefix) const {
  archive.put(prefix + "previous_time_s", optional_array(previous_time_s_));
  archive.put(prefix + "previous_x_um", {previous_x_um_});
  archive.put(prefix + "entry_time_s", optional_array(entry_time_s_));
  archive.put(prefix + "exit_time_s", optional_array(exit_time_s_));
}

void NarrowSectionTransit::restore_state(StateArchive& archive, const std::string& prefix) {
  previous_time_s_ = optional_of(archive.take(prefix + "previous_time_s", std::nullopt));
  previous_x_um_ = archive.take_number(prefix + "previous_x_um");
  entry_time_s_ = optional_of(archive.take(prefix + "entry_time_s", std::nullopt));
  exit_time_s_ = optional_of(archive.take(prefix + "exit_time_s", std::nullopt));
}

}  // namespace rbcsim::cases
