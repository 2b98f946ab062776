// The plain reference kernel: collide every fluid node, then stream into a second array, with
// readable loops over the velocity set. It stays forever as the yardstick of the optimised kernel
// (docs/architecture.md); keep it simple rather than fast.
#pragma once

#include "lattice/fluid_kernel.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace rbcsim::lattice {

// Collision of one node: f holds the pre-collision populations and receives the post-collision
// ones; `force` is the force density of the step. TRT with Guo forcing (Guo, Zheng & Shi 2002):
//   f*_i = f_i - w+ (f+_i - feq+_i) - w- (f-_i - feq-_i) + (1 - w+/2) S+_i + (1 - w-/2) S-_i,
//   S_i  = w_i [ (c_i - u) . F / c_s^2 + (c_i . u)(c_i . F) / c_s^4 ],
// where + and - are the parts even and odd under c_i -> -c_i. With w+ = w- this is BGK with the
// (1 - 1/(2 tau)) Guo prefactor. Returns the density and velocity u = (sum f c + F/2) / rho.
void collide_node_reference(std::array<double, kDirections>& f, const std::array<double, 3>& force,
                            const RelaxationRates& rates, double& density,
                            std::array<double, 3>& velocity);

// Collision at every fluid node of `arrays` (natural layout), in place, at the node's own rates
// when the parameters give per-node viscosity classes; stores density and velocity.
void collide_reference(const LatticeSetup& setup, FluidArrays& arrays,
                       const StepParameters& parameters);

// Streaming of the post-collision populations `post` (natural layout, population i of node n at
// [i * stride + n]) into the pre-collision populations `pre` of the fluid nodes (same layout), with
// every boundary rule. `arrays` supplies the density and velocity of the collision that produced
// `post`; `arrival_time` sets the Lees-Edwards offset.
void stream_reference(const LatticeSetup& setup, const FluidArrays& arrays,
                      const std::vector<double>& post, std::vector<double>& pre,
                      std::size_t arrival_time, std::size_t stride);

class ReferenceKernel final : public FluidKernel {
 public:
  explicit ReferenceKernel(const LatticeSetup& setup);
  void step(FluidArrays& arrays, const StepParameters& parameters) override;

 private:
  const LatticeSetup& setup_;
  std::vector<double> streamed_;
};

}  // namespace rbcsim::lattice
