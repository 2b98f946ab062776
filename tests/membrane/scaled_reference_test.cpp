// The scaled stress-free reference (membrane/reference_state.hpp, scaled_reference) and a model's
// reference replaced (MembraneModel::set_reference), which a cell growing in the flow holds on its
// way to full size: the scaled reference is the one the scaled mesh captures, and a model given
// it computes the forces of a model built from the scaled mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "membrane/membrane_model.hpp"
#include "membrane/reference_state.hpp"
#include "mesh/topology.hpp"
#include "test_shapes.hpp"

namespace rbcsim::membrane {
namespace {

using membrane_test::forces_at;
using membrane_test::shipped;

mesh::TriangleMesh scaled(mesh::TriangleMesh mesh, double scale) {
  for (Vec3& p : mesh.positions_um) p = Vec3(1.0, -2.0, 0.5) + scale * p;
  return mesh;
}

void expect_relatively_near(const std::vector<double>& a, const std::vector<double>& b,
                            const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i], b[i], 1e-11 * (std::abs(b[i]) + 1e-3)) << what << " " << i;
  }
}

TEST(ScaledReference, IsTheReferenceOfTheScaledMesh) {
  const double scale = 0.85;
  for (const char* shape : {"discocyte", "stomatocyte-II"}) {
    const auto mesh = shipped(shape, 3);
    const auto topology = mesh::MeshTopology::build(mesh);
    const auto big = capture_reference_state(mesh.positions_um, mesh.triangles, topology);
    const auto small = scaled(mesh, scale);
    const auto expected = capture_reference_state(small.positions_um, small.triangles, topology);
    const auto actual = scaled_reference(big, scale);
    expect_relatively_near(actual.edge_lengths_um, expected.edge_lengths_um, "L0");
    expect_relatively_near(actual.dihedral_angles_rad, expected.dihedral_angles_rad, "theta0");
    expect_relatively_near(actual.triangle_areas_um2, expected.triangle_areas_um2, "A0");
    expect_relatively_near(actual.triangle_perimeters_um, expected.triangle_perimeters_um, "P0");
    expect_relatively_near(actual.vertex_offsets_um, expected.vertex_offsets_um, "M0_i");
    expect_relatively_near(actual.vertex_mean_curvatures_per_um,
                           expected.vertex_mean_curvatures_per_um, "H0");
    expect_relatively_near(
        {actual.volume_um3, actual.area_um2, actual.mean_volume_gradient_um2,
         actual.signed_curvature_sum_um, actual.absolute_curvature_sum_um},
        {expected.volume_um3, expected.area_um2, expected.mean_volume_gradient_um2,
         expected.signed_curvature_sum_um, expected.absolute_curvature_sum_um},
        "cell sums");
  }
  EXPECT_THROW((void)scaled_reference(ReferenceState{}, 0.0), std::invalid_argument);
}

TEST(ScaledReference, AModelGivenItComputesTheScaledMeshsForces) {
  const double scale = 0.85;
  const auto mesh = shipped("discocyte", 3);
  const auto small = scaled(mesh, scale);
  MembraneParameters parameters;  // the paper's six terms
  for (const char* kernel : {"optimised", "reference"}) {
    parameters.kernel = kernel;
    MembraneModel grown(mesh, parameters);
    const auto own = grown.reference();
    grown.set_reference(scaled_reference(own, scale));
    const MembraneModel built(small, parameters);
    // The small cell stretched along x and squeezed along y and z: its forces far from zero.
    auto positions = small.positions_um;
    for (Vec3& p : positions) p = p.cwiseProduct(Vec3(1.04, 0.98, 0.97));
    const auto expected = forces_at(built, positions);
    const auto actual = forces_at(grown, positions);
    double largest = 0.0;
    for (const Vec3& f : expected.total_pN) largest = std::max(largest, f.norm());
    ASSERT_GT(largest, 0.1) << kernel;
    for (std::size_t v = 0; v < positions.size(); ++v) {
      EXPECT_LT((actual.total_pN[v] - expected.total_pN[v]).norm(), 1e-9 * largest)
          << kernel << " vertex " << v;
    }
    // Back to its own reference: the forces of the model as built, bit for bit (at the full-size
    // cell stretched alike).
    grown.set_reference(own);
    const MembraneModel original(mesh, parameters);
    auto full_positions = mesh.positions_um;
    for (Vec3& p : full_positions) p = p.cwiseProduct(Vec3(1.04, 0.98, 0.97));
    const auto back = forces_at(grown, full_positions);
    const auto again = forces_at(original, full_positions);
    for (std::size_t v = 0; v < positions.size(); ++v) {
      EXPECT_EQ(back.total_pN[v], again.total_pN[v]) << kernel << " vertex " << v;
    }
  }
}

}  // namespace
}  // namespace rbcsim::membrane
