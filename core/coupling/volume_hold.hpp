// Holding a cell's enclosed volume while its vertices move (`ibm.hold_volume`; docs/physics.md,
// "The enclosed volume"). A red cell's membrane lets no water through on the time scales simulated
// here, but the velocity interpolated from the lattice is not exactly solenoidal at the membrane
// (the delta kernel smooths it, the friction step's correction is concentrated under the membrane),
// so a cell that moves with it gains or loses volume: a physiological discocyte in a 10 um tube
// lost 3.5 % in 12 ms (docs/validation.md). The hold removes from the vertex velocities v the
// multiple of the volume gradient g (g_i = dV/dx_i) that makes the volume's rate sum_i g_i . v_i
// zero: the smallest change of the velocities (in the sum of their squares) that does so, a
// uniform pressure-like push along the membrane's normals. A rigid motion has no volume rate, so it
// is left alone (to round-off).
#pragma once

#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/surface_energies.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace rbcsim::coupling {

class VolumeHold {
 public:
  VolumeHold(std::span<const mesh::Triangle> triangles, const mesh::MeshTopology& topology);

  // Corrects `velocities` of the vertices at `positions` (any one length unit L and time unit T)
  // and returns the volume rate removed, sum_i g_i . v_i before the correction (L^3 / T).
  double apply(std::span<const Vec3> positions, std::span<Vec3> velocities);

 private:
  membrane::SurfaceMeasures measures_;
  std::vector<Vec3> gradient_;
};

}  // namespace rbcsim::coupling
