// Moving the Lagrangian points with the interpolated fluid velocity (docs/architecture.md, step 5):
// massless vertices, dx/dt = u(x). Schemes are registered by name in one table
// ("ibm.point_advance": "euler" | "ab2"). Positions, velocities and dt in lattice units.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/state_archive.hpp"
#include "common/vec3.hpp"

namespace rbcsim::ibm {

// Forward Euler, x += u dt: HemoCell's scheme.
void advance_points(std::span<Vec3> positions_lu, std::span<const Vec3> velocities_lu,
                    double dt = 1.0);

struct PointAdvanceScheme {
  std::string_view name;
  int order;  // of accuracy in dt
  // previous_velocities is empty on the first step (no history yet); previous_dt is the step
  // that led to them.
  void (*advance)(std::span<Vec3> positions, std::span<const Vec3> velocities,
                  std::span<const Vec3> previous_velocities, double dt, double previous_dt);
  std::string_view description;
};

std::span<const PointAdvanceScheme> point_advance_schemes();

// Throws InputError("ibm.point_advance", ...) naming the known schemes for an unknown name.
const PointAdvanceScheme& find_point_advance_scheme(std::string_view name);

// A scheme plus the velocity history a multistep scheme needs. The history is sized on the first
// step and reused (no allocation per step after it).
class PointAdvancer {
 public:
  explicit PointAdvancer(const PointAdvanceScheme& scheme) : scheme_(&scheme) {}

  // Throws std::invalid_argument when the sizes differ from each other or from the history's
  // (call forget_history() first when the set of points changes on purpose).
  void advance(std::span<Vec3> positions_lu, std::span<const Vec3> velocities_lu, double dt = 1.0);

  // The next step starts like the first (e.g. after a restart or remeshing).
  void forget_history() { has_history_ = false; }

  const PointAdvanceScheme& scheme() const { return *scheme_; }

  // The history (checkpoints): `<prefix>advance.previous_dt` (-1 without history) and
  // `<prefix>advance.previous_velocities`. restore_state throws InputError for a history of
  // another size than point_count.
  void save_state(StateArchive& archive, const std::string& prefix) const;
  void restore_state(StateArchive& archive, const std::string& prefix, std::size_t point_count);

 private:
  const PointAdvanceScheme* scheme_;
  std::vector<Vec3> previous_velocities_;
  double previous_dt_ = 0.0;
  bool has_history_ = false;
};

}  // namespace rbcsim::ibm
