// The arrays a fluid kernel works on, what stays fixed during a run, and the stream-collide
// kernels chosen by name from one table ("reference", "optimised"). A kernel advances the
// populations by one time step: collision with Guo forcing at every fluid node, then streaming
// with the boundary rules of boundaries.hpp. All values are in lattice units.
#pragma once

#include "lattice/boundaries.hpp"
#include "lattice/collision.hpp"
#include "lattice/d3q19.hpp"
#include "lattice/lattice_grid.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace rbcsim::lattice {

// One array per Cartesian component, each in grid order.
using VectorField = std::array<std::vector<double>, 3>;

// How `FluidArrays::populations` is to be read.
enum class PopulationLayout {
  natural,  // slot i of node n holds the pre-collision f_i(n)
  swapped,  // slot i of node n holds the post-collision f*_opp(i)(n): the optimised (AA) kernel's
            // state between its local and its streaming step
};

// Values from the start of one population array to the next: the node count rounded up to an
// odd number of 64-byte cache lines. The kernels stream all 19 arrays side by side; at a stride
// that is a multiple of a large power of two (128^3 nodes: exactly 16 MiB) they all fall on the
// same cache sets and evict each other (measured: 128^3 ran at 30-32 MLUPS on one core, 130^3 at
// 70-72; docs/performance.md). With an odd number of lines the 19 arrays take distinct sets.
std::size_t population_stride(std::size_t node_count, std::size_t bytes_per_value = sizeof(double));

// How the populations are stored (`lattice.precision`). Single precision halves the bytes a step
// moves and stores f_i - w_i, the deviation from the equilibrium at rest (the "shifted
// equilibrium" of Skordos 1993 and of waLBerla's and OpenLB's float kernels): f_i itself is w_i
// plus a deviation of order u and rho - 1, and a float of f_i would lose that deviation's digits
// to w_i's. Every kernel computes in double; only the storage is single.
enum class Precision { double_precision, single_precision };

// The names of `lattice.precision`: "double", "single". find_precision throws InputError naming
// the key for any other.
struct PrecisionEntry {
  std::string_view name;
  Precision precision;
};
std::span<const PrecisionEntry> precisions();
Precision find_precision(std::string_view name);

struct FluidArrays {
  explicit FluidArrays(std::size_t node_count, Precision storage = Precision::double_precision);

  // Structure of arrays: population i of node n at populations[i * population_stride + n] (double
  // precision) or single_populations[...] = f_i - w_i (single). The padding after each array's
  // node_count values is never read. Slots i and opp(i) have the same weight, so the shift of a
  // slot does not depend on the layout.
  std::size_t population_stride;
  Precision precision;
  std::vector<double> populations;
  std::vector<float> single_populations;
  PopulationLayout layout = PopulationLayout::natural;
  bool single() const { return precision == Precision::single_precision; }
  // The population in slot `index` (= i * population_stride + node) of direction i, and its
  // replacement, in either storage.
  double population(int i, std::size_t index) const {
    return single() ? static_cast<double>(single_populations[index]) + kWeights[i]
                    : populations[index];
  }
  void set_population(int i, std::size_t index, double value) {
    if (single()) {
      single_populations[index] = static_cast<float>(value - kWeights[i]);
    } else {
      populations[index] = value;
    }
  }
  // Density and velocity u = (sum_i f_i c_i + F/2) / rho of the latest collision at each fluid
  // node (Guo et al. 2002); F is the force density of that step (field plus body force).
  std::vector<double> density;
  VectorField velocity;
  // Force density per node (for instance spread from membranes by the IBM).
  VectorField force_density;
};

// What a run keeps fixed: the box, its boundaries, and the optional Lees-Edwards plane.
struct LatticeSetup {
  LatticeGrid grid;
  BoundaryMap boundaries;
  // Velocity difference U between the image above and the box; no value: plain periodic in y.
  std::optional<double> lees_edwards_velocity;
  // How wall links are closed (boundaries.hpp); never null.
  const WallRule* wall_rule = &find_wall_rule("halfway");
};

// The weights of the wall link through which f_i enters the fluid node `node` (x - c_i is a wall
// node), from the setup's wall rule and the link's wall fraction. The next node x + c_i counts as
// fluid only if it is fluid and not across a sliding plane, so that both kernels find f*_h there.
WallLinkWeights wall_link_weights(const LatticeSetup& setup, std::size_t node, int direction);

// The nodes x in [begin, end) of one row of the lattice; begin == end: none.
struct ForcedSpan {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
};

struct StepParameters {
  RelaxationRates rates;
  std::array<double, 3> body_force = {0.0, 0.0, 0.0};  // uniform force density
  bool force_field_active = false;  // false: FluidArrays::force_density is zero and not read
  // With force_field_active: per row of nodes (y + ny z), the nodes whose force density may be
  // non-zero (outside them it is zero and need not be read). Null: every node of every row.
  const ForcedSpan* forced_spans = nullptr;
  std::size_t time = 0;             // steps completed before this one
  // Per-node viscosity (collision.hpp), both or neither: the class of every node in grid order, and
  // the rates of each of the kViscosityClasses classes. Null: every node relaxes at `rates`.
  const ViscosityClass* viscosity_classes = nullptr;
  const RelaxationRates* class_rates = nullptr;
};

class FluidKernel {
 public:
  virtual ~FluidKernel() = default;
  virtual void step(FluidArrays& arrays, const StepParameters& parameters) = 0;
};

struct FluidKernelEntry {
  std::string_view name;
  std::string_view summary;
  std::unique_ptr<FluidKernel> (*make)(const LatticeSetup& setup);
};

std::span<const FluidKernelEntry> fluid_kernels();

// The entry of the named kernel. Throws rbcsim::InputError naming `lattice.kernel` for an
// unknown name.
const FluidKernelEntry& find_fluid_kernel(std::string_view name);

// Checks that `setup` suits every kernel (rbcsim::InputError naming `lattice.lees_edwards` when a
// sliding plane holds non-fluid nodes) and makes the named kernel. The kernel keeps a reference
// to `setup`, which must outlive it.
std::unique_ptr<FluidKernel> make_fluid_kernel(std::string_view name, const LatticeSetup& setup);

// The populations without the padding: kDirections * node_count values, population i of node n at
// [i * node_count + n] (the layout of checkpoints and of the solver's interface), and back.
std::vector<double> packed_populations(const FluidArrays& arrays);
void unpack_populations(std::span<const double> packed, FluidArrays& arrays);

// The populations as stored (packed; in single precision the floats f_i - w_i, exactly), and
// back: what a checkpoint keeps, so that a resumed run is bit-identical in either precision.
std::vector<double> stored_populations(const FluidArrays& arrays);
void restore_stored_populations(std::span<const double> stored, FluidArrays& arrays);

// The pre-collision populations in natural layout, packed, whichever layout `arrays` holds.
// `time` is the number of steps completed (it sets the Lees-Edwards offset of a pending stream).
std::vector<double> pre_collision_populations(const LatticeSetup& setup, const FluidArrays& arrays,
                                              std::size_t time);

}  // namespace rbcsim::lattice
