#include "ibm/point_advance.hpp"

#include <array>
#include <stdexcept>

#include "common/registry.hpp"

namespace rbcsim::ibm {
namespace {

void euler_scheme(std::span<Vec3> positions, std::span<const Vec3> velocities,
                  std::span<const Vec3>, double dt, double) {
  advance_points(positions, velocities, dt);
}

// Second-order Adams-Bashforth with variable step: x += dt ((1 + r/2) u_n - (r/2) u_{n-1}),
// r = dt / dt_prev; exact for a velocity linear in time. Falls back to Euler on the first step.
void adams_bashforth2_scheme(std::span<Vec3> positions, std::span<const Vec3> velocities,
                             std::span<const Vec3> previous_velocities, double dt,
                             double previous_dt) {
  if (previous_velocities.empty()) {
    advance_points(positions, velocities, dt);
    return;
  }
  const double half_ratio = 0.5 * dt / previous_dt;
#pragma omp parallel for schedule(static)
  for (std::size_t point = 0; point < positions.size(); ++point) {
    positions[point] +=
        dt * ((1.0 + half_ratio) * velocities[point] - half_ratio * previous_velocities[point]);
  }
}

constexpr std::array kSchemes{
    PointAdvanceScheme{"euler", 1, euler_scheme, "forward Euler x += u dt (HemoCell)"},
    PointAdvanceScheme{"ab2", 2, adams_bashforth2_scheme,
                       "2nd-order Adams-Bashforth, Euler on the first step"},
};

}  // namespace

void advance_points(std::span<Vec3> positions_lu, std::span<const Vec3> velocities_lu, double dt) {
  if (positions_lu.size() != velocities_lu.size()) {
    throw std::invalid_argument("advance_points: positions and velocities differ in number");
  }
#pragma omp parallel for schedule(static)
  for (std::size_t point = 0; point < positions_lu.size(); ++point) {
    positions_lu[point] += dt * velocities_lu[point];
  }
}

std::span<const PointAdvanceScheme> point_advance_schemes() { return kSchemes; }

const PointAdvanceScheme& find_point_advance_scheme(std::string_view name) {
  return find_entry(kSchemes, name, "ibm.point_advance");
}

void PointAdvancer::advance(std::span<Vec3> positions_lu, std::span<const Vec3> velocities_lu,
                            double dt) {
  if (positions_lu.size() != velocities_lu.size() ||
      (has_history_ && previous_velocities_.size() != velocities_lu.size())) {
    throw std::invalid_argument("PointAdvancer::advance: the number of points changed");
  }
  const std::span<const Vec3> history =
      has_history_ ? std::span<const Vec3>(previous_velocities_) : std::span<const Vec3>();
  scheme_->advance(positions_lu, velocities_lu, history, dt, previous_dt_);
  previous_velocities_.assign(velocities_lu.begin(), velocities_lu.end());
  previous_dt_ = dt;
  has_history_ = true;
}

void PointAdvancer::save_state(StateArchive& archive, const std::string& prefix) const {
  archive.put(prefix + "advance.previous_dt", {has_history_ ? previous_dt_ : -1.0});
  archive.put(prefix + "advance.previous_velocities",
              has_history_ ? std::span<const Vec3>(previous_velocities_) : std::span<const Vec3>());
}

void PointAdvancer::restore_state(StateArchive& archive, const std::string& prefix,
                                  std::size_t point_count) {
  const double previous_dt = archive.take_number(prefix + "advance.previous_dt");
  has_history_ = previous_dt >= 0.0;
  previous_dt_ = has_history_ ? previous_dt : 0.0;
  previous_velocities_.resize(has_history_ ? point_count : 0);
  archive.take(prefix + "advance.previous_velocities", previous_velocities_);
}

}  // namespace rbcsim::ibm
