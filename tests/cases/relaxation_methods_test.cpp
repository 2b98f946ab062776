// The relaxation table and FIRE: the same equilibrium as overdamped Euler where Euler can find
// it, convergence where the total-curvature kinks stall a plain force criterion, and loud limits.
#include "cases/relaxation_methods.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "cases/stretch_case.hpp"
#include "common/errors.hpp"
#include "stretch_test_support.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::cases::find_relaxation_method;
using rbcsim::membrane::MembraneModel;
using rbcsim::membrane::MembraneParameters;
using rbcsim::membrane::RelaxationSettings;
namespace support = rbcsim::cases::testing;

double max_norm(const std::vector<Vec3>& vectors) {
  double largest = 0.0;
  for (const auto& v : vectors) largest = std::max(largest, v.norm());
  return largest;
}

struct Pulled {
  rbcsim::cases::StretchCell cell;
  std::vector<Vec3> external_pN;
};

Pulled pulled_discocyte(int level, double force_pN) {
  auto cell = rbcsim::cases::prepare_stretch_cell(support::evans_fung_discocyte(level), {});
  auto external =
      rbcsim::cases::tweezer_forces_pN(cell.mesh.vertex_count(), cell.patches, force_pN);
  return {std::move(cell), std::move(external)};
}

TEST(RelaxationMethods, TableNamesAndUnknownName) {
  EXPECT_EQ(rbcsim::cases::relaxation_method_names(), (std::vector<std::string>{"fire", "euler"}));
  try {
    find_relaxation_method("newton");
    FAIL() << "no error";
  } catch (const rbcsim::InputError& error) {
    EXPECT_STREQ(error.what(),
                 "stretch.quasi_static.relaxation: \"newton\" is not one of fire, euler");
  }
}

// Without the total-curvature term the energy is smooth and both methods meet the same force
// criterion, so they must find the same shape (within residual / stiffness of the softest mode:
// 1e-4 pN against ~1 pN/um leaves ~1e-4 um; 2e-3 um allows for the slowest mode).
TEST(RelaxationMethods, FireFindsEulersEquilibriumOnASmoothEnergy) {
  auto pulled = pulled_discocyte(3, 10.0);
  MembraneParameters parameters;
  parameters.forces = {"link", "bend", "area", "volume", "area_difference"};
  const MembraneModel model(pulled.cell.mesh, parameters);
  const RelaxationSettings settings{.force_tolerance_pN = 1e-4, .max_iterations = 50000};
  auto by_fire = pulled.cell.mesh.positions_um;
  auto by_euler = pulled.cell.mesh.positions_um;
  const auto fire = find_relaxation_method("fire")(model, by_fire, pulled.external_pN, settings);
  const auto euler = find_relaxation_method("euler")(model, by_euler, pulled.external_pN, settings);
  ASSERT_TRUE(fire.converged);
  ASSERT_TRUE(euler.converged);
  double largest_um = 0.0;
  for (std::size_t i = 0; i < by_fire.size(); ++i) {
    largest_um = std::max(largest_um, (by_fire[i] - by_euler[i]).norm());
  }
  EXPECT_LT(largest_um, 2e-3);
  // The energy is smooth: every vertex is balanced to the tolerance, so the membrane holds each
  // patch against its tweezer, sum = -F x, to n * tolerance.
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  model.compute(by_fire, workspace, forces);
  Vec3 on_patch = Vec3::Zero();
  for (const auto v : pulled.cell.patches.positive_end) on_patch += forces.total_pN[v];
  EXPECT_NEAR((on_patch + Vec3(10.0, 0, 0)).norm(), 0.0,
              1e-4 * static_cast<double>(pulled.cell.patches.positive_end.size()));
  std::printf("FIRE %zu iterations, Euler %zu; largest vertex distance %.2e um\n", fire.iterations,
              euler.iterations, largest_um);
  EXPECT_LT(fire.iterations * 5, euler.iterations);  // the point of FIRE
}

// With all six terms the stretched discocyte has flat edges at equilibrium: the model's net force
// keeps a kink jump far above the tolerance there, the smoothed force converges
// (curvature_kinks.hpp).
TEST(RelaxationMethods, FireConvergesThroughTheTotalCurvatureKinks) {
  auto pulled = pulled_discocyte(3, 30.0);
  const MembraneModel model(pulled.cell.mesh, MembraneParameters{});
  const RelaxationSettings settings{.force_tolerance_pN = 1e-4, .max_iterations = 20000};
  auto positions = pulled.cell.mesh.positions_um;
  const auto result =
      find_relaxation_method("fire")(model, positions, pulled.external_pN, settings);
  ASSERT_TRUE(result.converged) << result.max_force_pN;
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  model.compute(positions, workspace, forces);
  auto raw_net = forces.total_pN;
  for (std::size_t i = 0; i < raw_net.size(); ++i) raw_net[i] += pulled.external_pN[i];
  std::printf("%zu iterations; raw net force %.3e pN, smoothed %.3e pN\n", result.iterations,
              max_norm(raw_net), result.max_force_pN);
  EXPECT_GT(max_norm(raw_net), 10 * settings.force_tolerance_pN);
}

TEST(RelaxationMethods, IterationLimitIsReportedAsNotConverged) {
  auto pulled = pulled_discocyte(3, 30.0);
  const MembraneModel model(pulled.cell.mesh, MembraneParameters{});
  auto positions = pulled.cell.mesh.positions_um;
  const auto result = find_relaxation_method("fire")(
      model, positions, pulled.external_pN, {.force_tolerance_pN = 1e-4, .max_iterations = 5});
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.iterations, 5u);
  EXPECT_GT(result.max_force_pN, 1e-4);
}

}  // namespace
