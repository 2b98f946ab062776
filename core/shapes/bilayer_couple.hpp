// The bilayer-couple model of the red cell's shape (Lim, Wortis & Mukhopadhyay, PNAS 99:16766,
// 2002): bending + area-difference elasticity of the bilayer + the skeleton's nonlinear
// elasticity against its own reference (membrane/surface_energies.hpp), at a held membrane area
// and enclosed volume. As a minimise::FireProblem: the force is minus the energy gradient
// projected onto the tangent space of the two constraints, which are restored after every step.
#pragma once

#include <span>
#include <vector>

#include "common/vec3.hpp"
#include "membrane/surface_energies.hpp"
#include "mesh/topology.hpp"
#include "mesh/triangle_mesh.hpp"
#include "minimise/constraints.hpp"
#include "minimise/fire.hpp"

namespace rbcsim::shapes {

struct BilayerCoupleParameters {
  membrane::HelfrichBendingParameters bending;
  membrane::AreaDifferenceParameters area_difference;
  membrane::SkeletonParameters skeleton;
  double area_um2 = 0.0;    // held membrane area
  double volume_um3 = 0.0;  // held enclosed volume
};

// The energy of each term, pN um.
struct BilayerCoupleEnergies {
  double bending_pN_um = 0.0;
  double area_difference_pN_um = 0.0;
  double skeleton_pN_um = 0.0;
  double total_pN_um() const { return bending_pN_um + area_difference_pN_um + skeleton_pN_um; }
};

class BilayerCoupleModel final : public minimise::FireProblem {
 public:
  // `skeleton_reference` is the skeleton's stress-free triangulation (same connectivity as the
  // shapes it is evaluated on); the model keeps a reference to `topology` and `triangles`.
  BilayerCoupleModel(std::span<const mesh::Triangle> triangles, const mesh::MeshTopology& topology,
                     membrane::SkeletonReference skeleton_reference,
                     const BilayerCoupleParameters& parameters);

  // Energies at `positions` and, when `gradient_pN` is not empty, the total gradient (overwritten).
  BilayerCoupleEnergies evaluate(std::span<const Vec3> positions_um, std::span<Vec3> gradient_pN);

  // A minimisation follows a path of states (deflation, skeleton stiffening, a change of the
  // relaxed area difference), so these can be moved between stages.
  void set_volume_um3(double volume_um3);
  void set_skeleton(const membrane::SkeletonParameters& skeleton);
  void set_relaxed_curvature_sum_um(double curvature_sum_um);
  const BilayerCoupleParameters& parameters() const { return parameters_; }

  // minimise::FireProblem
  void forces(std::span<const Vec3> positions_um, std::span<Vec3> forces_pN) override;
  double stiffest_mode(std::span<const Vec3> positions_um) override;
  void project(std::span<const Vec3> positions_um, std::span<Vec3> vectors) override;
  void restore(std::span<Vec3> positions_um) override;

 private:
  std::span<const mesh::Triangle> triangles_;
  const mesh::MeshTopology& topology_;
  membrane::SkeletonReference skeleton_reference_;
  BilayerCoupleParameters parameters_;
  membrane::SurfaceMeasures measures_;
  minimise::ConstraintSet constraints_;
  double mean_edge_um_ = 0.0;
};

}  // namespace rbcsim::shapes
