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

// Populations laid out `stride` values apart, as kDirections * node_count packed values.
std::vector<double> without_padding(std::span<const double> populations, std::size_t stride,
                                    std::size_t node_count) {
  std::vector<double> packed(kDirections * node_count);
  for (int i = 0; i < kDirections; ++i) {
    const auto array = populations.begin() + i * stride;
    std::copy(array, array + node_count, packed.begin() + i * node_count);
  }
  return packed;
}

}  // namespace

std::size_t population_stride(std::size_t node_count) {
  constexpr std::size_t kValuesPerLine = 64 / sizeof(double);
  const std::size_t lines = (node_count + kValuesPerLine - 1) / kValuesPerLine;
  return (lines % 2 == 1 ? lines : lines + 1) * kValuesPerLine;
}

FluidArrays::FluidArrays(std::size_t node_count)
    : population_stride(lattice::population_stride(node_count)),
      populations(kDirections * population_stride, 0.0),
      density(node_count, 0.0),
      velocity{std::vector<double>(node_count, 0.0), std::vector<double>(node_count, 0.0),
               std::vector<double>(node_count, 0.0)},
      force_density{std::vector<double>(node_count, 0.0), std::vector<double>(node_count, 0.0),
                    std::vector<double>(node_count, 0.0)} {}

std::span<const FluidKernelEntry> fluid_kernels() { return kFluidKernels; }

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
  return without_padding(arrays.populations, arrays.population_stride, arrays.density.size());
}

void unpack_populations(std::span<const double> packed, FluidArrays& arrays) {
  const std::size_t node_count = arrays.density.size();
  for (int i = 0; i < kDirections; ++i) {
    const auto array = packed.begin() + i * node_count;
    std::copy(array, array + node_count, arrays.populations.begin() + i * arrays.population_stride);
  }
}

std::vector<double> pre_collision_populations(const LatticeSetup& setup, const FluidArrays& arrays,
                                              std::size_t time) {
  if (arrays.layout == PopulationLayout::natural) {
    return packed_populations(arrays);
  }
  const std::size_t node_count = setup.grid.node_count();
  const std::size_t stride = arrays.population_stride;
  std::vector<double> post(arrays.populations.size());
  for (int i = 0; i < kDirections; ++i) {
    for (std::size_t node = 0; node < node_count; ++node) {
      post[i * stride + node] = arrays.populations[kOpposite[i] * stride + node];
    }
  }
  std::vector<double> pre = post;
  stream_reference(setup, arrays, post, pre, time);
  return without_padding(pre, stride, node_count);
}

}  // namespace rbcsim::lattice
