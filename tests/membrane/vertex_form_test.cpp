// The per-vertex form of the angle terms (membrane.distribution = vertex, HemoCell 2.x): the
// patch offset and the push pattern against a shape whose answer is known by symmetry, momentum
// conservation, rest, thread-count independence and the error paths.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "membrane/force_law.hpp"
#include "membrane/force_terms.hpp"
#include "membrane/membrane_model.hpp"
#include "membrane/vertex_patch.hpp"
#include "test_shapes.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::membrane::ForceLaw;
using rbcsim::membrane::MembraneModel;
using rbcsim::membrane::MembraneParameters;
using rbcsim::mesh::TriangleMesh;
namespace shapes = rbcsim::membrane_test;

// A regular hexagon of radius 1 um in z = 0 with apexes at (0, 0, +-h): vertices 0-5 the hexagon
// (counter-clockwise seen from +z), 6 the top apex, 7 the bottom one.
TriangleMesh bipyramid(double height_um) {
  TriangleMesh mesh;
  for (int i = 0; i < 6; ++i) {
    const double angle = std::numbers::pi / 3.0 * i;
    mesh.positions_um.emplace_back(std::cos(angle), std::sin(angle), 0.0);
  }
  mesh.positions_um.emplace_back(0.0, 0.0, height_um);
  mesh.positions_um.emplace_back(0.0, 0.0, -height_um);
  for (int i = 0; i < 6; ++i) {
    const int next = (i + 1) % 6;
    mesh.triangles.push_back({i, next, 6});
    mesh.triangles.push_back({next, i, 7});
  }
  return mesh;
}

MembraneParameters vertex_form(const std::vector<std::string>& terms) {
  MembraneParameters parameters;
  parameters.forces = terms;
  parameters.distribution = "vertex";
  parameters.kernel = "reference";
  parameters.vertex_force_cap_pN = INFINITY;
  return parameters;
}

TEST(VertexPatch, TheApexOfABipyramidSitsItsHeightAboveItsRing) {
  for (const double height_um : {0.5, 1.0, 2.0}) {
    const auto mesh = bipyramid(height_um);
    const auto topology = rbcsim::mesh::MeshTopology::build(mesh);
    std::vector<Vec3> normals(8);
    std::vector<double> offsets_um(8);
    rbcsim::membrane::measure_vertex_patches(mesh.positions_um, mesh.triangles, topology, normals,
                                             offsets_um);
    EXPECT_NEAR((normals[6] - Vec3(0, 0, 1)).norm(), 0.0, 1e-14);
    EXPECT_NEAR((normals[7] - Vec3(0, 0, -1)).norm(), 0.0, 1e-14);
    EXPECT_NEAR(offsets_um[6], height_um, 1e-14);
    EXPECT_NEAR(offsets_um[7], height_um, 1e-14);
    // An equator vertex: ring = two hexagon neighbours (centroid 0.75 of the way out in its
    // direction, cos 60 = 1/2 each) and the two apexes (on the axis): offset 1 - 2 (1/2) / 4.
    EXPECT_NEAR(normals[0].dot(Vec3(1, 0, 0)), 1.0, 1e-14);
    EXPECT_NEAR(offsets_um[0], 0.75, 1e-14);
  }
}

TEST(VertexPatch, EveryVertexOfASphereBulgesOutward) {
  const auto mesh = shapes::sphere(3, 3.0);
  const auto topology = rbcsim::mesh::MeshTopology::build(mesh);
  const auto n = mesh.positions_um.size();
  std::vector<Vec3> normals(n);
  std::vector<double> offsets_um(n);
  rbcsim::membrane::measure_vertex_patches(mesh.positions_um, mesh.triangles, topology, normals,
                                           offsets_um);
  for (std::size_t v = 0; v < n; ++v) {
    EXPECT_GT(normals[v].dot(mesh.positions_um[v].normalized()), 0.99) << v;
    EXPECT_GT(offsets_um[v], 0.0) << v;
  }
}

// Both apexes raised from h0 = 1 to h: by the mirror and six-fold symmetry every equator vertex
// keeps its offset (the apexes sit on the axis) and its normal is radial, so the force on the top
// apex is its own push alone: (0, 0, P) with P = -(k kBT / L0) slope(d).
TEST(VertexForm, TheApexOfARaisedBipyramidFeelsExactlyItsOwnPush) {
  const auto rest = bipyramid(1.0);
  auto raised = rest.positions_um;
  raised[6].z() = 1.1;
  raised[7].z() = -1.1;
  const double mean_edge_um = (6.0 * 1.0 + 12.0 * std::sqrt(2.0)) / 18.0;
  for (const std::string term : {"bend", "area_difference", "total_curvature"}) {
    const auto parameters = vertex_form({term});
    const MembraneModel model(rest, parameters);
    const auto forces = shapes::forces_at(model, raised);
    double slope = 0.0;
    double k_kBT = 0.0;
    if (term == "bend") {
      const auto law = ForceLaw::with_linear_term(rbcsim::membrane::VertexBendingTerm::kTau);
      slope = law.slope(0.1 / mean_edge_um);
      k_kBT = parameters.k_bend_kBT;
    } else if (term == "area_difference") {
      slope = ForceLaw::with_linear_term(parameters.tau_area_difference)
                  .slope(forces.cell.area_difference);
      k_kBT = parameters.k_area_difference_kBT;
    } else {
      slope = ForceLaw::with_linear_term(parameters.tau_total_curvature)
                  .slope(forces.cell.total_curvature);
      k_kBT = parameters.k_total_curvature_kBT;
    }
    const double push_pN =
        -k_kBT * parameters.thermal_energy_pN_um / parameters.force_length_scale_um * slope;
    ASSERT_GT(std::abs(push_pN), 1e-3) << term;
    // Raised apexes: every measure grows, so each term pushes the apex back down.
    EXPECT_LT(push_pN, 0.0) << term;
    const Vec3 apex_pN = forces.total_pN[6];
    EXPECT_NEAR(apex_pN.z(), push_pN, 1e-12 * std::abs(push_pN)) << term;
    EXPECT_NEAR(apex_pN.head<2>().norm(), 0.0, 1e-12 * std::abs(push_pN)) << term;
  }
}

TEST(VertexForm, ConservesMomentumAndVanishesAtRestOnEveryShippedShape) {
  const auto parameters = vertex_form({"bend", "area_difference", "total_curvature"});
  for (std::size_t s = 0; s < shapes::property_test_shape_count(); ++s) {
    const auto& [name, mesh] = shapes::property_test_shape(s);
    const MembraneModel model(mesh, parameters);
    const auto at_rest = shapes::forces_at(model, mesh.positions_um);
    for (const auto& force : at_rest.total_pN) EXPECT_EQ(force.norm(), 0.0) << name;
    auto moved = mesh.positions_um;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-0.02, 0.02);
    for (auto& position : moved) position += Vec3(jitter(random), jitter(random), jitter(random));
    const auto forces = shapes::forces_at(model, moved);
    Vec3 sum = Vec3::Zero();
    double scale = 0.0;
    for (const auto& force : forces.total_pN) {
      sum += force;
      scale += force.norm();
    }
    ASSERT_GT(scale, 0.0) << name;
    EXPECT_LT(sum.norm(), 1e-12 * scale) << name;
  }
}

TEST(VertexForm, ForcesDoNotDependOnTheThreadCount) {
  const auto mesh = shapes::shipped("echinocyte-III", 3);
  const MembraneModel model(mesh, vertex_form({"bend", "area_difference", "total_curvature"}));
  auto moved = mesh.positions_um;
  for (std::size_t v = 0; v < moved.size(); ++v) moved[v] *= 1.0 + 0.01 * std::sin(double(v));
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = shapes::forces_at(model, moved);
  omp_set_num_threads(2);
  const auto two = shapes::forces_at(model, moved);
  omp_set_num_threads(threads);
  for (std::size_t v = 0; v < moved.size(); ++v) EXPECT_EQ(one.total_pN[v], two.total_pN[v]);
}

// Building a model of the bipyramid with `parameters` is an InputError whose message has `text`.
void expect_refused(const MembraneParameters& parameters, const std::string& text) {
  try {
    const MembraneModel model(bipyramid(1.0), parameters);
    FAIL() << "accepted; expected an error with: " << text;
  } catch (const rbcsim::InputError& error) {
    EXPECT_THAT(error.what(), testing::HasSubstr(text));
  }
}

TEST(VertexForm, TheOptimisedKernelAndAnUnknownNameSayWhatIsAccepted) {
  auto parameters = vertex_form({"bend"});
  parameters.kernel = "optimised";
  expect_refused(parameters, "membrane.kernel=reference");
  parameters.distribution = "hinge";
  expect_refused(parameters, "paper, gradient, vertex");
}

}  // namespace
