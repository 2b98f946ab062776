#include "shapes/bilayer_couple.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "minimise/stiffness.hpp"

namespace rbcsim::shapes {
namespace {

// The constraints are restored to this fraction of their value: far below anything the shape
// analysis resolves (v to 1e-3), far above round-off.
constexpr double kRelativeConstraintTolerance = 1e-10;
// Finite-difference probe of the stiffness estimate, relative to the mean edge (as the membrane's).
constexpr double kProbeFraction = 1e-6;

// A held surface measure (area or volume), evaluated on its own measures (the light pass of
// SurfaceMeasures::measure_area_and_volume): `measure` returns the value, `gradient` writes its
// gradient.
template <class Value, class Gradient>
minimise::Constraint surface_constraint(std::string name, std::span<const mesh::Triangle> triangles,
                                        const mesh::MeshTopology& topology, double target,
                                        Value value, Gradient gradient) {
  auto measures = std::make_shared<membrane::SurfaceMeasures>(triangles, topology);
  return {std::move(name),
          [measures, value, gradient](std::span<const Vec3> positions, std::span<Vec3> out) {
            measures->measure_area_and_volume(positions);
            gradient(*measures, out);
            return value(*measures);
          },
          target, kRelativeConstraintTolerance * target};
}

minimise::Constraint area_constraint(std::span<const mesh::Triangle> triangles,
                                     const mesh::MeshTopology& topology, double area_um2) {
  return surface_constraint(
      "membrane area", triangles, topology, area_um2,
      [](const membrane::SurfaceMeasures& m) { return m.area_um2; }, membrane::area_gradient);
}

minimise::Constraint volume_constraint(std::span<const mesh::Triangle> triangles,
                                       const mesh::MeshTopology& topology, double volume_um3) {
  return surface_constraint(
      "enclosed volume", triangles, topology, volume_um3,
      [](const membrane::SurfaceMeasures& m) { return m.geometry.volume_um3; },
      membrane::volume_gradient);
}

}  // namespace

BilayerCoupleModel::BilayerCoupleModel(std::span<const mesh::Triangle> triangles,
                                       const mesh::MeshTopology& topology,
                                       membrane::SkeletonReference skeleton_reference,
                                       const BilayerCoupleParameters& parameters)
    : triangles_(triangles),
      topology_(topology),
      skeleton_reference_(std::move(skeleton_reference)),
      parameters_(parameters),
      measures_(triangles, topology),
      constraints_({area_constraint(triangles, topology, parameters.area_um2),
                    volume_constraint(triangles, topology, parameters.volume_um3)},
                   topology.vertex_count()) {
  // The mean reference edge sets the stiffness probe: sqrt(area per triangle) is its scale.
  double area = 0.0;
  for (double a : skeleton_reference_.areas_um2) area += a;
  mean_edge_um_ = std::sqrt(4.0 * area / (std::sqrt(3.0) * static_cast<double>(triangles.size())));
}

BilayerCoupleEnergies BilayerCoupleModel::evaluate(std::span<const Vec3> positions_um,
                                                   std::span<Vec3> gradient_pN) {
  measures_.measure(positions_um);
  std::vector<Vec3> scratch;
  std::span<Vec3> gradient = gradient_pN;
  if (gradient.empty()) {
    scratch.assign(positions_um.size(), Vec3::Zero());
    gradient = scratch;
  } else {
    std::fill(gradient.begin(), gradient.end(), Vec3::Zero());
  }
  BilayerCoupleEnergies energies;
  energies.bending_pN_um = membrane::HelfrichBending{parameters_.bending}.add(measures_, gradient);
  energies.area_difference_pN_um =
      membrane::AreaDifferenceElasticity{parameters_.area_difference}.add(measures_, gradient);
  energies.skeleton_pN_um =
      membrane::SkeletonElasticity{parameters_.skeleton, &skeleton_reference_}.add(measures_,
                                                                                   gradient);
  return energies;
}

void BilayerCoupleModel::set_volume_um3(double volume_um3) {
  parameters_.volume_um3 = volume_um3;
  constraints_.set_target(1, volume_um3);
}

void BilayerCoupleModel::set_skeleton(const membrane::SkeletonParameters& skeleton) {
  parameters_.skeleton = skeleton;
}

void BilayerCoupleModel::set_relaxed_curvature_sum_um(double curvature_sum_um) {
  parameters_.area_difference.relaxed_curvature_sum_um = curvature_sum_um;
}

void BilayerCoupleModel::forces(std::span<const Vec3> positions_um, std::span<Vec3> forces_pN) {
  evaluate(positions_um, forces_pN);
  for (auto& force : forces_pN) force = -force;
  constraints_.project(positions_um, forces_pN);
}

double BilayerCoupleModel::stiffest_mode(std::span<const Vec3> positions_um) {
  return minimise::estimate_stiffest_mode(
      [this](std::span<const Vec3> positions, std::span<Vec3> forces_pN) {
        forces(positions, forces_pN);
      },
      positions_um, kProbeFraction * mean_edge_um_);
}

void BilayerCoupleModel::project(std::span<const Vec3> positions_um, std::span<Vec3> vectors) {
  constraints_.project(positions_um, vectors);
}

void BilayerCoupleModel::restore(std::span<Vec3> positions_um) {
  constraints_.restore(positions_um);
}

}  // namespace rbcsim::shapes
