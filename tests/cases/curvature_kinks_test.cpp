// The smoothing of the total-curvature kinks: the sign-carrying edge force g_j must be exactly
// the jump of the membrane model's own force across theta_j = 0, and the smoothed force must have
// no jump.
#include "cases/curvature_kinks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <utility>

#include "membrane/vertex_patch.hpp"
#include "mesh/geometry.hpp"
#include "stretch_test_support.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::cases::CurvatureKinks;
using rbcsim::membrane::MembraneModel;
using rbcsim::membrane::MembraneParameters;

MembraneParameters total_curvature_only(const std::string& distribution) {
  MembraneParameters parameters;
  parameters.forces = {"total_curvature"};
  parameters.distribution = distribution;
  parameters.vertex_force_cap_pN = INFINITY;
  return parameters;
}

// Moves the edge's wing0 along its triangle's normal until theta_j = target (Newton on
// d theta / d wing0 = -n0 / h0, mesh/hinge.hpp).
void set_angle(std::vector<Vec3>& positions, const rbcsim::mesh::Edge& edge, double target_rad) {
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Vec3 v0 = positions[edge.vertex0];
    const Vec3 axis = positions[edge.vertex1] - v0;
    const Vec3 normal = axis.cross(positions[edge.wing0] - v0);
    const double height_um = normal.norm() / axis.norm();
    const double angle = rbcsim::mesh::signed_dihedral_angle_rad(positions, edge);
    positions[edge.wing0] += (angle - target_rad) * height_um * normal.normalized();
  }
}

struct KinkSetup {
  rbcsim::mesh::TriangleMesh mesh;
  std::vector<Vec3> deformed_um;
  std::size_t edge_index = 0;
};

// The N = 3 discocyte stretched affinely (so the total curvature deviates and g_j is not zero),
// and its flattest edge.
KinkSetup stretched_discocyte(const MembraneModel& model, const rbcsim::mesh::TriangleMesh& mesh) {
  KinkSetup setup{mesh, mesh.positions_um, 0};
  for (auto& p : setup.deformed_um) p = p.cwiseProduct(Vec3(1.15, 0.95, 0.9));
  const auto& edges = model.topology().edges();
  double flattest = INFINITY;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const double angle =
        std::abs(rbcsim::mesh::signed_dihedral_angle_rad(setup.deformed_um, edges[e]));
    if (angle < flattest) flattest = angle, setup.edge_index = e;
  }
  return setup;
}

// The largest change of a vertex's force between two force arrays, over `vertices`.
template <class Vertices>
double largest_jump(const std::vector<Vec3>& above, const std::vector<Vec3>& below,
                    const Vertices& vertices) {
  double jump = 0.0;
  for (const auto vertex : vertices) {
    jump = std::max(jump, (above[static_cast<std::size_t>(vertex)] -
                           below[static_cast<std::size_t>(vertex)])
                              .norm());
  }
  return jump;
}

class Distribution : public ::testing::TestWithParam<const char*> {};

TEST_P(Distribution, SignForceIsHalfTheJumpOfTheModelForceAcrossAFlatEdge) {
  const auto mesh = rbcsim::cases::testing::evans_fung_discocyte(3);
  const MembraneModel model(mesh, total_curvature_only(GetParam()));
  const auto setup = stretched_discocyte(model, mesh);
  const auto& edge = model.topology().edges()[setup.edge_index];
  constexpr double kAngle_rad = 1e-7;
  auto above = setup.deformed_um;
  set_angle(above, edge, kAngle_rad);
  auto below = setup.deformed_um;
  set_angle(below, edge, -kAngle_rad);

  auto workspace = model.make_workspace();
  auto forces_above = model.make_forces();
  auto forces_below = model.make_forces();
  model.compute(above, workspace, forces_above);
  model.compute(below, workspace, forces_below);
  const CurvatureKinks kinks(model);
  const auto flat = kinks.flat_edges(above, forces_above);
  const auto found = std::find_if(flat.begin(), flat.end(), [&](const auto& candidate) {
    return candidate.vertices[0] == edge.vertex0 && candidate.vertices[1] == edge.vertex1;
  });
  ASSERT_NE(found, flat.end());
  const auto& kink = *found;
  EXPECT_NEAR(kink.angle_rad, kAngle_rad, 1e-12);
  double jump_scale = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto vertex = kink.vertices[k];
    const Vec3 half_jump = 0.5 * (forces_above.total_pN[vertex] - forces_below.total_pN[vertex]);
    jump_scale = std::max(jump_scale, half_jump.norm());
    // The rest of the force changes by O(theta) between the two shapes: 1e-7 relative.
    EXPECT_NEAR((half_jump - kink.sign_force_pN[k]).norm(), 0.0,
                1e-5 * kink.sign_force_pN[k].norm() + 1e-9)
        << "vertex slot " << k;
  }
  EXPECT_GT(jump_scale, 1e-3);  // a real jump, not two zeros
}

// The smoothed force is continuous across theta_j = 0: on either side of a flat edge it differs
// by O(theta), where the model's jumps by 2 g_j; at |theta_j| >= eps it is the model's own.
TEST_P(Distribution, SmoothedForceIsContinuousAcrossAFlatEdge) {
  const auto mesh = rbcsim::cases::testing::evans_fung_discocyte(3);
  const MembraneModel model(mesh, total_curvature_only(GetParam()));
  const auto setup = stretched_discocyte(model, mesh);
  const auto& edge = model.topology().edges()[setup.edge_index];
  const CurvatureKinks kinks(model);
  auto workspace = model.make_workspace();
  const auto smoothed_at = [&](double angle_rad) {
    auto positions = setup.deformed_um;
    set_angle(positions, edge, angle_rad);
    auto forces = model.make_forces();
    model.compute(positions, workspace, forces);
    auto net = forces.total_pN;
    kinks.smooth(positions, forces, net);
    return std::pair(forces.total_pN, net);
  };
  const auto [model_above, smoothed_above] = smoothed_at(1e-7);
  const auto [model_below, smoothed_below] = smoothed_at(-1e-7);
  const std::array<std::int32_t, 4> hinge = {edge.vertex0, edge.vertex1, edge.wing0, edge.wing1};
  const double model_jump = largest_jump(model_above, model_below, hinge);
  const double smoothed_jump = largest_jump(smoothed_above, smoothed_below, hinge);
  EXPECT_GT(model_jump, 1e-3);
  EXPECT_LT(smoothed_jump, 1e-4 * model_jump);
  // Outside the window nothing changes.
  const auto [model_outside, smoothed_outside] =
      smoothed_at(2 * rbcsim::cases::kCurvatureSmoothing_rad);
  for (const auto vertex : hinge) {
    EXPECT_EQ(model_outside[vertex], smoothed_outside[vertex]);
  }
  // Without the term nothing changes either.
  MembraneParameters smooth;
  smooth.forces = {"link", "area", "volume"};
  const MembraneModel without_term(mesh, smooth);
  const CurvatureKinks inactive(without_term);
  EXPECT_FALSE(inactive.active());
  auto forces = without_term.make_forces();
  std::vector<Vec3> untouched(without_term.vertex_count(), Vec3(1, 2, 3));
  inactive.smooth(setup.deformed_um, forces, untouched);
  for (const auto& force : untouched) EXPECT_EQ(force, Vec3(1, 2, 3));
}

// flat_edges screens the edges before it takes their angles: it must still find exactly the edges
// with |theta_j| < eps, also those a hair inside or outside the window.
TEST_P(Distribution, FlatEdgesAreExactlyTheEdgesInsideTheWindow) {
  const auto mesh = rbcsim::cases::testing::evans_fung_discocyte(3);
  const MembraneModel model(mesh, total_curvature_only(GetParam()));
  const auto setup = stretched_discocyte(model, mesh);
  const auto& edges = model.topology().edges();
  const CurvatureKinks kinks(model);
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  constexpr double kWindow_rad = rbcsim::cases::kCurvatureSmoothing_rad;
  for (const double target_rad :
       {0.5 * kWindow_rad, kWindow_rad * (1.0 - 1e-9), -kWindow_rad * (1.0 - 1e-9),
        kWindow_rad * (1.0 + 1e-9), -kWindow_rad * (1.0 + 1e-9), 3.0 * kWindow_rad}) {
    auto positions = setup.deformed_um;
    set_angle(positions, edges[setup.edge_index], target_rad);
    model.compute(positions, workspace, forces);
    // (vertex0, vertex1, angle) of every edge inside the window, by the exact angle.
    std::vector<std::tuple<std::int32_t, std::int32_t, double>> expected;
    for (const auto& edge : edges) {
      const double angle_rad = rbcsim::mesh::signed_dihedral_angle_rad(positions, edge);
      if (std::abs(angle_rad) < kWindow_rad) {
        expected.emplace_back(edge.vertex0, edge.vertex1, angle_rad);
      }
    }
    std::vector<std::tuple<std::int32_t, std::int32_t, double>> found;
    for (const auto& kink : kinks.flat_edges(positions, forces)) {
      found.emplace_back(kink.vertices[0], kink.vertices[1], kink.angle_rad);
    }
    EXPECT_EQ(found, expected) << "target " << target_rad << " rad";
    // The edge set near the window's edge is where a screen too narrow would lose it.
    const auto& target = edges[setup.edge_index];
    const bool target_found = std::ranges::any_of(found, [&](const auto& entry) {
      return std::get<0>(entry) == target.vertex0 && std::get<1>(entry) == target.vertex1;
    });
    EXPECT_EQ(target_found, std::abs(target_rad) < kWindow_rad) << "target " << target_rad;
  }
  // A degenerate hinge (wing0 on vertex0, a triangle of no area, its normal exactly zero): its
  // exact angle is atan2(0, 0) = 0, flat, and the screen must leave it to the exact test.
  auto positions = setup.deformed_um;
  const auto& target = edges[setup.edge_index];
  positions[target.wing0] = positions[target.vertex0];
  ASSERT_EQ(rbcsim::mesh::signed_dihedral_angle_rad(positions, target), 0.0);
  const auto flat = kinks.flat_edges(positions, forces);
  EXPECT_TRUE(std::ranges::any_of(flat, [&](const auto& kink) {
    return kink.vertices[0] == target.vertex0 && kink.vertices[1] == target.vertex1;
  }));
}

INSTANTIATE_TEST_SUITE_P(Both, Distribution, ::testing::Values("gradient", "paper"));

// The vertex form pushes a patch with sign(M_i) (membrane/vertex_patch.hpp): the model's force
// jumps where a patch offset crosses zero, the smoothed one does not.
TEST(VertexFormKinks, SmoothedForceIsContinuousAcrossAFlatPatch) {
  const auto mesh = rbcsim::cases::testing::evans_fung_discocyte(3);
  auto parameters = total_curvature_only("vertex");
  parameters.kernel = "reference";
  const MembraneModel model(mesh, parameters);
  const auto setup = stretched_discocyte(model, mesh);
  const auto& topology = model.topology();
  const auto n = model.vertex_count();
  std::vector<Vec3> normals(n);
  std::vector<double> offsets_um(n);
  const auto measure = [&](const std::vector<Vec3>& positions) {
    rbcsim::membrane::measure_vertex_patches(positions, model.triangles(), topology, normals,
                                             offsets_um);
  };
  measure(setup.deformed_um);
  std::size_t flattest = 0;
  for (std::size_t v = 1; v < n; ++v) {
    if (std::abs(offsets_um[v]) < std::abs(offsets_um[flattest])) flattest = v;
  }
  const CurvatureKinks kinks(model);
  auto workspace = model.make_workspace();
  // Moves the flattest vertex along its normal until its offset is target_um (dM/dx = n, nearly).
  const auto smoothed_at = [&](double target_um) {
    auto positions = setup.deformed_um;
    for (int iteration = 0; iteration < 30; ++iteration) {
      measure(positions);
      positions[flattest] += (target_um - offsets_um[flattest]) * normals[flattest];
    }
    auto forces = model.make_forces();
    model.compute(positions, workspace, forces);
    auto net = forces.total_pN;
    kinks.smooth(positions, forces, net);
    return std::pair(forces.total_pN, net);
  };
  const auto [model_above, smoothed_above] = smoothed_at(1e-9);
  const auto [model_below, smoothed_below] = smoothed_at(-1e-9);
  std::vector<std::size_t> every_vertex(n);
  std::iota(every_vertex.begin(), every_vertex.end(), std::size_t{0});
  const double model_jump = largest_jump(model_above, model_below, every_vertex);
  const double smoothed_jump = largest_jump(smoothed_above, smoothed_below, every_vertex);
  EXPECT_GT(model_jump, 1e-3);
  EXPECT_LT(smoothed_jump, 1e-4 * model_jump);
}

}  // namespace
