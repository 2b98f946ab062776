// The implementations of MembraneModel::compute, chosen by name (`membrane.kernel`) from one
// table (membrane_kernel.cpp):
//   "reference"  one plain loop per force term (the classes of force_terms.hpp): the readable
//                definition of the forces, kept forever to test the optimised kernel against.
//   "optimised"  the six terms fused into one pass over the edges and one over the triangles,
//                then one gather per vertex (optimised_kernel.cpp). The default. A term it has
//                not fused (helfrich, local_area) runs beside them as its reference class.
// Both fill the same MembraneForces; their results agree to round-off (tests/membrane,
// kernel_equivalence_test.cpp) and neither depends on the thread count.
#pragma once

#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/cell_geometry.hpp"
#include "membrane/force_term.hpp"
#include "membrane/membrane_forces.hpp"
#include "membrane/optimised_scratch.hpp"

namespace rbcsim::membrane {

class MembraneModel;

// Caller-owned work arrays of one cell, made by MembraneModel::make_workspace (sized for its
// mesh and kernel; each kernel fills only its own part), so that compute() never allocates.
struct MembraneWorkspace {
  // The reference kernel's.
  CellGeometry geometry;
  TermScratch scratch;
  // The optimised kernel's.
  OptimisedScratch optimised;
  // MembraneModel's, for the dissipative terms (both kernels): their geometry, scratch and
  // forces.
  CellGeometry dissipative_geometry;
  TermScratch dissipative_scratch;
  std::vector<TermForces> dissipative;
};

// One implementation of the elastic membrane forces of a model (the terms of
// MembraneModel::kernel_term_names(); the dissipative ones are the model's own). Built once per
// model; compute() reads the model's mesh, reference and parameters, so a kernel never outlives
// or copies them.
class MembraneKernel {
 public:
  virtual ~MembraneKernel() = default;
  virtual MembraneWorkspace make_workspace(const MembraneModel& model) const = 0;
  // The contract of MembraneModel::compute for the kernel's terms, the first
  // kernel_term_names().size() entries of forces.terms (positions already checked to be one per
  // vertex).
  virtual void compute(const MembraneModel& model, std::span<const Vec3> positions_um,
                       MembraneWorkspace& workspace, MembraneForces& forces,
                       ForceDetail detail) const = 0;
};

// The registry of kernels (`membrane.kernel`). A factory may throw InputError for parameters or
// a reference its terms cannot work with.
struct MembraneKernelEntry {
  std::string_view name;
  std::unique_ptr<MembraneKernel> (*make)(const MembraneModel& model);
};
std::span<const MembraneKernelEntry> membrane_kernel_table();
// Throws InputError naming `membrane.kernel` for an unknown name.
const MembraneKernelEntry& find_membrane_kernel(std::string_view name);

std::unique_ptr<MembraneKernel> make_reference_kernel(const MembraneModel& model);
// Sizes the reference kernel's part of a workspace (its geometry and term scratch), which the
// optimised kernel also uses for the terms it has not fused.
void size_term_workspace(const MembraneModel& model, MembraneWorkspace& workspace);
// The terms the optimised kernel fuses, in registry order; it runs any other beside them as the
// reference kernel does.
std::vector<std::string> fused_force_term_names();
std::unique_ptr<MembraneKernel> make_optimised_kernel(const MembraneModel& model);

// The force cap on one vertex's total force (MembraneParameters::vertex_force_cap_pN), shared
// by the kernels: scales total_pN down to the cap and returns true when it was above. `finite`
// becomes false when the force is not finite (NaN or infinite).
inline bool clamp_to_force_cap(Vec3& total_pN, double cap_pN, bool& finite) {
  const double magnitude_pN = total_pN.norm();
  finite = std::isfinite(magnitude_pN);
  if (magnitude_pN > cap_pN) {
    total_pN *= cap_pN / magnitude_pN;
    return true;
  }
  return false;
}
// Throws RuntimeFailure naming the first vertex whose force is not finite, if any
// (first_non_finite < vertex_count).
void require_finite_forces(std::size_t first_non_finite, std::size_t vertex_count);

}  // namespace rbcsim::membrane
