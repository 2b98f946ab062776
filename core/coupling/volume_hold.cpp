#include "coupling/volume_hold.hpp"

#include <stdexcept>
#include <string>

namespace rbcsim::coupling {

VolumeHold::VolumeHold(std::span<const mesh::Triangle> triangles,
                       const mesh::MeshTopology& topology)
    : measures_(triangles, topology), gradient_(topology.vertex_count()) {}

double VolumeHold::apply(std::span<const Vec3> positions, std::span<Vec3> velocities) {
  if (positions.size() != gradient_.size() || velocities.size() != gradient_.size()) {
    throw std::invalid_argument("VolumeHold: " + std::to_string(positions.size()) +
                                " positions and " + std::to_string(velocities.size()) +
                                " velocities for " + std::to_string(gradient_.size()) +
                                " vertices");
  }
  // The measures name their units um, but are the same sums in any unit.
  measures_.measure_area_and_volume(positions);
  membrane::volume_gradient(measures_, gradient_);
  double rate = 0.0;
  double gradient_squared = 0.0;
  for (std::size_t v = 0; v < gradient_.size(); ++v) {
    rate += gradient_[v].dot(velocities[v]);
    gradient_squared += gradient_[v].squaredNorm();
  }
  const double multiple = rate / gradient_squared;
  for (std::size_t v = 0; v < gradient_.size(); ++v) velocities[v] -= multiple * gradient_[v];
  return rate;
}

}  // namespace rbcsim::coupling
