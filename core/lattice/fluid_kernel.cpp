#include "lattice/fluid_kernel.hpp"

#include "common/errors.hpp"
#include "common/registry.hpp"
#include "lattice/optimised_kernel.hpp"
#include "lattice/reference_kernel.hpp"

#include <algorithm>
#include <string>

namespace rbcsim::lattice {
namespace {

template <class Kernel>
std::unique_ptr<FluidKernel> make(const LatticeSetup& setup) {
  return std::make_unique<Kernel>(setup);
}

constexpr std::array kFluidKernels = {
    FluidKernelEntry{"optimised", "fused stream-collide, AA in-place streaming, vectorised",
                     make<OptimisedKernel>},
    FluidKernelEntry{"reference", "plain collide then stream, two arrays", make<ReferenceKernel>},
};

constexpr std::array kPrecisions = {PrecisionEntry{"double", Precision::double_precision},
                                    PrecisionEntry{"single", Precision::single_precision}};

// A sliding plane must be plain fluid: the interpolated sources of a crossing population are then
// fluid whatever the offset.
void check_lees_edwards_planes(const LatticeSetup& setup) {
  const LatticeGrid& grid = setup.grid;
  for (int z = 0; z < grid.nz(); ++z) {
    for (int x = 0; x < grid.nx(); ++x) {
      for (const int y : {0, grid.ny() - 1}) {
        if (!setup.boundaries.is_fluid(grid.index(x, y, z))) {
          throw InputError("shear.boundary",
                           "the sliding planes y = 0 and y = ny - 1 must hold fluid only, node (" +
                               std::to_string(x) + ", " + std::to_string(y) + ", " +
                               std::to_string(z) + ") is not fluid");
        }
      }
    }
  }
}

// The populations of `arrays` (any storage) as kDirections * node_count packed doubles, read
// through slot(i) = the direction whose array is read for population i (i itself, or opp(i) for
// the swapped layout's post-collision values).
template <class Slot>
std::vector<double> packed_from(const FluidArrays& arrays, Slot&& slot) {
  const std::size_t node_count = arrays.density.size();
  std::vector<double> packed(kDirections * node_count);
  for (int i = 0; i < kDirections; ++i) {
    const std::size_t array = static_cast<std::size_t>(slot(i)) * arrays.population_stride;
    for (std::size_t node = 0; node < node_count; ++node) {
      packed[i * node_count + node] = arrays.population(slot(i), array + node);
    }
  }
  return packed;
}

}  // namespace

std::size_t population_stride(std::size_t node_count, std::size_t bytes_per_value) {
  const std::size_t values_per_line = 64 / bytes_per_value;
  const std::size_t lines = (node_count + values_per_line - 1) / values_per_line;
  return (lines % 2 == 1 ? lines : lines + 1) * values_per_line;
}

FluidArrays::FluidArrays(std::size_t node_count, Precision storage)
    : population_stride(lattice::population_stride(
          node_count, storage == Precision::single_precision ? sizeof(float) : sizeof(double))),
      precision(storage),
      populations(single() ? 0 : kDirections * population_stride, 0.0),
      single_populations(single() ? kDirections * population_stride : 0, 0.0F),
      density(node_count, 0.0),
      velocity{std::vector<double>(node_count, 0.0), std::vector<double>(node_count, 0.0),
               std::vector<double>(node_count, 0.0)},
      force_density{std::vector<double>(node_count, 0.0), std::vector<double>(node_count, 0.0),
                    std::vector<double>(node_count, 0.0)} {}

std::span<const FluidKernelEntry> fluid_kernels() { return kFluidKernels; }

std::span<const PrecisionEntry> precisions() { return kPrecisions; }

Precision find_precision(std::string_view name) {
  return find_entry(kPrecisions, name, "lattice.precision").precision;
}

const FluidKernelEntry& find_fluid_kernel(std::string_view name) {
  return find_entry(kFluidKernels, name, "lattice.kernel");
}

std::unique_ptr<FluidKernel> make_fluid_kernel(std::string_view name, const LatticeSetup& setup) {
  const FluidKernelEntry& entry = find_fluid_kernel(name);
  if (setup.lees_edwards_velocity) {
    check_lees_edwards_planes(setup);
  }
  return entry.make(setup);
}

WallLinkWeights wall_link_weights(const LatticeSetup& setup, std::size_t node, int direction) {
  const LatticeGrid& grid = setup.grid;
  const auto& c = kVelocities[direction];
  const int behind_y = grid.coordinates(node)[1] + c[1];
  const bool across_sliding_plane =
      setup.lees_edwards_velocity && (behind_y < 0 || behind_y >= grid.ny());
  const bool behind_is_fluid =
      !across_sliding_plane && setup.boundaries.is_fluid(grid.periodic_neighbour(node, c));
  return setup.wall_rule->weights(setup.boundaries.wall_fraction(node, kOpposite[direction]),
                                  behind_is_fluid);
}

std::vector<double> packed_populations(const FluidArrays& arrays) {
  return packed_from(arrays, [](int i) { return i; });
}

void unpack_populations(std::span<const double> packed, FluidArrays& arrays) {
  const std::size_t node_count = arrays.density.size();
  for (int i = 0; i < kDirections; ++i) {
    for (std::size_t node = 0; node < node_count; ++node) {
      arrays.set_population(i, i * arrays.population_stride + node, packed[i * node_count + node]);
    }
  }
}

std::vector<double> stored_populations(const FluidArrays& arrays) {
  if (!arrays.single()) return packed_populations(arrays);
  const std::size_t node_count = arrays.density.size();
  std::vector<double> stored(kDirections * node_count);
  for (std::size_t i = 0; i < kDirections; ++i) {
    const auto array = arrays.single_populations.begin() + i * arrays.population_stride;
    std::copy(array, array + node_count, stored.begin() + i * node_count);
  }
  return stored;
}

void restore_stored_populations(std::span<const double> stored, FluidArrays& arrays) {
  if (!arrays.single()) {
    unpack_populations(stored, arrays);
    return;
  }
  const std::size_t node_count = arrays.density.size();
  for (std::size_t i = 0; i < kDirections; ++i) {
    for (std::size_t node = 0; node < node_count; ++node) {
      arrays.single_populations[i * arrays.population_stride + node] =
          static_cast<float>(stored[i * node_count + node]);
    }
  }
}

std::vector<double> pre_collision_populations(const LatticeSetup& setup, const FluidArrays& arrays,
                                              std::size_t time) {
  if (arrays.layout == PopulationLayout::natural) {
    return packed_populations(arrays);
  }
  // Swapped: slot opp(i) holds f*_i; stream those post-collision values as the reference does.
  const std::size_t node_count = setup.grid.node_count();
  std::vector<double> post = packed_from(arrays, [](int i) { return kOpposite[i]; });
  std::vector<double> pre = post;
  stream_reference(setup, arrays, post, pre, time, node_count);
  return pre;
}

}  // namespace rbcsim::lattice
