// The optimised kernel: fused stream-collide with one population array streamed in place by the
// AA pattern (Bailey et al., "Accelerating lattice Boltzmann fluid flow simulations using graphics
// processors", ICPP 2009). Two alternating steps:
//   local step      (layout natural -> swapped): read f_i(x) from slot i of x, collide, write
//                   f*_i to slot opp(i) of x. No neighbour is touched.
//   streaming step  (layout swapped -> natural): read f_i(x) = f*_i(x - c_i) from slot opp(i) of
//                   x - c_i, collide, write f*_i to slot i of x + c_i.
// Each node reads exactly the slots it writes, so a step needs no second array (304 bytes of
// population traffic per node and step) and the order of the nodes, hence the thread count, cannot
// change a result. Bulk nodes run through a vectorised loop over x with the 19 directions written
// out; nodes next to a boundary or on a Lees-Edwards plane take a per-link path with precomputed
// links, or, when every link is plain fluid or a resting half-way wall, a gather and scatter
// through precomputed slots (WalledNode). Rows collide without the forcing terms outside the span
// where the force field is non-zero (StepParameters::forced_spans), and without any where there
// is no body force either. Lees-Edwards populations go through small ghost planes: filled before
// the streaming step from the swapped state, and emptied into the natural state after it.
// Interpolated wall links (boundaries.hpp) read f*_h(x), f*_i(x) and f*_h(x + c_i), h = opp(i): for
// the populations of a local step, their local part is stored before the streaming step overwrites
// f*_i(x) in slot h of x, and f*_h(x + c_i) is x's own gathered population; for those of a
// streaming step, x's scatter writes the local part and f*_h(x + c_i) is added once the step is
// complete, when it has arrived in slot h of x. After every streaming step the state equals the
// reference kernel's; after a local step, its density and velocity do.
#pragma once

#include "lattice/fluid_kernel.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rbcsim::lattice {

class OptimisedKernel final : public FluidKernel {
 public:
  explicit OptimisedKernel(const LatticeSetup& setup);
  void step(FluidArrays& arrays, const StepParameters& parameters) override;

  // `wall`: half-way bounce-back; `interpolated_wall`: any other weights of the wall rule.
  enum class LinkKind : std::uint8_t {
    fluid,
    wall,
    pressure_outlet,
    lees_edwards,
    interpolated_wall
  };

  // A fluid node that needs the per-link path in the streaming step. For link i (the population
  // arriving from x - c_i): `source` is x - c_i (fluid), the slot of the ghost planes
  // (Lees-Edwards) or the index of the link in the list of interpolated wall links; `value` is
  // 2 w_i c_i.u_w / c_s^2 (wall) or the outlet density.
  struct LinkedNode {
    std::size_t node = 0;
    std::uint8_t kind[kDirections] = {};
    std::size_t source[kDirections] = {};
    double value[kDirections] = {};
  };

  // A linked node whose links are all plain fluid or resting half-way walls (most of the nodes
  // along a tube's wall): its streaming step is a gather and a scatter through fixed slots, with
  // no case per link. Population i is read from slot read_slot[i] of node read_node[i] (slot
  // opp(i) of x - c_i, or slot i of x itself behind a wall) and f*_i written to slot
  // write_slot[i] of write_node[i] (slot i of x + c_i, or slot opp(i) of x before a wall).
  struct WalledNode {
    std::uint32_t node = 0;
    std::uint32_t read_node[kDirections] = {};
    std::uint32_t write_node[kDirections] = {};
    std::uint8_t read_slot[kDirections] = {};
    std::uint8_t write_slot[kDirections] = {};
  };

  // A wall link closed by interpolated bounce-back (boundaries.hpp): f_i enters `node` from the
  // wall; `behind` is node + c_i.
  struct InterpolatedLink {
    std::size_t node = 0;
    int direction = 0;
    WallLinkWeights weights;
    double wall_coefficient = 0.0;  // 2 w_i c_i.u_w / c_s^2
    std::size_t behind = 0;
  };

  struct Run {
    int x_begin;
    int x_end;
  };

 private:
  // kPerNodeRates: every node relaxes at the rates of its viscosity class (collision.hpp). Real:
  // the population storage, double or float (fluid_kernel.hpp, Precision).
  template <bool kPerNodeRates, class Real>
  void step_with(FluidArrays& arrays, const StepParameters& parameters);
  // Each row of nodes collides with the forcing it needs (StepParameters::forced_spans): the force
  // field, the body force alone, or none.
  template <bool kPerNodeRates, class Real>
  void local_step(FluidArrays& arrays, const StepParameters& parameters) const;
  template <bool kPerNodeRates, class Real>
  void streaming_step(FluidArrays& arrays, const StepParameters& parameters);
  void store_wall_local_parts(const FluidArrays& arrays);
  void add_wall_parts_behind(FluidArrays& arrays) const;
  void fill_lees_edwards_ghosts(const FluidArrays& arrays, std::size_t arrival_time);
  void empty_lees_edwards_ghosts(FluidArrays& arrays, std::size_t arrival_time) const;

  const LatticeSetup& setup_;
  std::size_t plane_size_;  // nx * nz: one ghost plane per direction
  // Per row r = y + ny z, entries [begin[r], begin[r + 1]) of the flat lists.
  std::vector<std::size_t> fluid_run_begin_;
  std::vector<Run> fluid_runs_;  // every fluid node (local step)
  std::vector<std::size_t> bulk_run_begin_;
  std::vector<Run> bulk_runs_;  // fluid nodes with fluid neighbours only, never straddling x = 1
                                // or x = nx - 1, so that the periodic wrap is one pointer offset
  std::vector<std::size_t> linked_begin_;
  std::vector<LinkedNode> linked_nodes_;  // nodes with other links (walled_nodes_ below)
  std::vector<std::size_t> walled_begin_;
  std::vector<WalledNode> walled_nodes_;
  std::vector<InterpolatedLink> interpolated_links_;
  // Per interpolated link, the local part of the population entering at the streaming step, taken
  // before that step overwrites f*_i(x) (slot opp(i) of x, which node x + c_i streams from).
  std::vector<double> wall_local_parts_;
  std::vector<double> ghost_in_;   // ghost_in_[i * plane + x + nx z]: f_i entering through a plane
  std::vector<double> ghost_out_;  // ghost_out_[k * plane + x + nx z]: f*_opp(k) leaving the node
};

}  // namespace rbcsim::lattice
