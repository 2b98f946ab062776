// Overdamped relaxation: a noisy discocyte returns to its reference shape.
#include "membrane/relaxation.hpp"

#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "test_shapes.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::membrane::MembraneModel;
using rbcsim::membrane::MembraneParameters;
namespace shapes = rbcsim::membrane_test;

// Largest vertex distance between `moved` and `reference` after removing the rigid motion that
// best maps one onto the other (Kabsch: least-squares rotation and translation).
double max_distance_after_rigid_alignment_um(const std::vector<Vec3>& moved,
                                             const std::vector<Vec3>& reference) {
  const auto count = static_cast<double>(moved.size());
  Vec3 moved_center = Vec3::Zero();
  Vec3 reference_center = Vec3::Zero();
  for (std::size_t i = 0; i < moved.size(); ++i) {
    moved_center += moved[i] / count;
    reference_center += reference[i] / count;
  }
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < moved.size(); ++i) {
    covariance += (moved[i] - moved_center) * (reference[i] - reference_center).transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d correction = Eigen::Matrix3d::Identity();
  correction(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
  const Eigen::Matrix3d rotation = svd.matrixV() * correction * svd.matrixU().transpose();
  double largest = 0.0;
  for (std::size_t i = 0; i < moved.size(); ++i) {
    const Vec3 aligned = rotation * (moved[i] - moved_center) + reference_center;
    largest = std::max(largest, (aligned - reference[i]).norm());
  }
  return largest;
}

class NoisyCellRelaxes : public ::testing::TestWithParam<const char*> {};

TEST_P(NoisyCellRelaxes, BackToItsReferenceShape) {
  const auto mesh = shapes::discocyte(3);
  MembraneParameters parameters;  // Table 2 discocyte, all six terms
  parameters.distribution = GetParam();
  const MembraneModel model(mesh, parameters);
  const double diameter_um = 2 * 3.91;
  // Noise: each vertex moved by up to 10 % of the mean edge length, in a random direction.
  auto positions =
      shapes::with_noise(mesh.positions_um, 0.1 * shapes::mean_edge_length_um(mesh), 3);
  const double initial_error_um =
      max_distance_after_rigid_alignment_um(positions, mesh.positions_um);

  rbcsim::membrane::RelaxationSettings settings;
  settings.force_tolerance_pN = 1e-3;
  settings.max_iterations = 20000;
  const auto start = std::chrono::steady_clock::now();
  const auto result = rbcsim::membrane::relax_membrane(model, positions, {}, settings);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double final_error_um = max_distance_after_rigid_alignment_um(positions, mesh.positions_um);
  std::printf(
      "%s: %zu iterations, %.2f s wall, lambda_max %.1f pN/um, residual %.2e pN, "
      "max distance to reference %.4f um (initially %.4f um), cap hits %zu\n",
      GetParam(), result.iterations, wall_s, result.stiffest_mode_pN_per_um, result.max_force_pN,
      final_error_um, initial_error_um, result.capped_vertex_count);

  ASSERT_TRUE(result.converged) << "residual " << result.max_force_pN << " pN";
  EXPECT_LT(final_error_um, 0.01 * diameter_um);
  // The noise alone is below 1 % of the diameter at this resolution, so also require that most
  // of it is gone.
  EXPECT_LT(final_error_um, 0.1 * initial_error_um);
}

INSTANTIATE_TEST_SUITE_P(Distributions, NoisyCellRelaxes, ::testing::Values("paper", "gradient"));

struct Extents {
  double axial_um;       // along x, the pull
  double transverse_um;  // along y
};

Extents stretched_extents(const MembraneModel& model, const std::vector<Vec3>& reference_um,
                          double total_force_pN) {
  // The five vertices of largest x are pulled by +F/5 each along x, the five of smallest x by -F/5.
  std::vector<std::size_t> order(reference_um.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return reference_um[a].x() < reference_um[b].x();
  });
  std::vector<Vec3> external_pN(reference_um.size(), Vec3::Zero());
  for (std::size_t k = 0; k < 5; ++k) {
    external_pN[order[k]] = Vec3(-total_force_pN / 5, 0, 0);
    external_pN[order[order.size() - 1 - k]] = Vec3(total_force_pN / 5, 0, 0);
  }
  auto positions = reference_um;
  const auto result =
      rbcsim::membrane::relax_membrane(model, positions, external_pN, {.force_tolerance_pN = 1e-3});
  EXPECT_TRUE(result.converged) << "residual " << result.max_force_pN << " pN";
  std::printf("F = %.1f pN: %zu iterations\n", total_force_pN, result.iterations);
  Vec3 low = positions.front();
  Vec3 high = positions.front();
  for (const auto& p : positions) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return {high.x() - low.x(), high.y() - low.y()};
}

// Pulled at both ends, the cell lengthens along the pull and narrows across it, and at small
// forces the response is linear (doubling the force doubles the extension, up to the cubic
// corrections of the force law, a few per cent at these strains).
TEST(Relaxation, ExternalForcesStretchTheCellLinearlyAtSmallForce) {
  const auto mesh = shapes::discocyte(3);
  const MembraneModel model(mesh, MembraneParameters{});
  const auto at_rest = stretched_extents(model, mesh.positions_um, 0.0);
  const auto pulled = stretched_extents(model, mesh.positions_um, 1.0);
  const auto pulled_twice = stretched_extents(model, mesh.positions_um, 2.0);
  const double extension_um = pulled.axial_um - at_rest.axial_um;
  EXPECT_GT(extension_um, 0.0);
  EXPECT_LT(pulled.transverse_um, at_rest.transverse_um);
  std::printf("axial extension %.5f um at 1 pN, %.5f um at 2 pN\n", extension_um,
              pulled_twice.axial_um - at_rest.axial_um);
  EXPECT_NEAR((pulled_twice.axial_um - at_rest.axial_um) / extension_um, 2.0, 0.1);
}

TEST(Relaxation, IterationLimitIsReportedAsNotConverged) {
  const auto mesh = shapes::sphere(2, 3.0);
  const MembraneModel model(mesh, MembraneParameters{});
  auto positions = shapes::with_noise(mesh.positions_um, 0.05, 5);
  rbcsim::membrane::RelaxationSettings settings;
  settings.max_iterations = 3;
  const auto result = rbcsim::membrane::relax_membrane(model, positions, {}, settings);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.iterations, 3u);
  EXPECT_GT(result.max_force_pN, settings.force_tolerance_pN);
}

}  // namespace
