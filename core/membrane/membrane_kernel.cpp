// The registry of membrane kernels (`membrane.kernel`) and what the kernels share.
#include "membrane/membrane_kernel.hpp"

#include <string>

#include "common/errors.hpp"
#include "common/registry.hpp"

namespace rbcsim::membrane {
namespace {

constexpr MembraneKernelEntry kKernels[] = {
    {"optimised", make_optimised_kernel},
    {"reference", make_reference_kernel},
};

}  // namespace

std::span<const MembraneKernelEntry> membrane_kernel_table() { return kKernels; }

const MembraneKernelEntry& find_membrane_kernel(std::string_view name) {
  return find_entry(kKernels, name, "membrane.kernel");
}

void require_finite_forces(std::size_t first_non_finite, std::size_t vertex_count) {
  if (first_non_finite < vertex_count) {
    throw RuntimeFailure("membrane forces: the force on vertex " +
                         std::to_string(first_non_finite) + " is not finite (unstable state)");
  }
}

}  // namespace rbcsim::membrane
