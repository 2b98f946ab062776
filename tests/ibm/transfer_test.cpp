// Spreading and interpolation through the stencil: conservation of the total force, exactness on
// constant and linear fields, adjointness, agreement with the plain reference, and independence
// of the OpenMP thread count.
#include "ibm/transfer.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "ibm/reference_transfer.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::ibm::DeltaKernel;
using rbcsim::ibm::find_delta_kernel;
using rbcsim::ibm::GridView;
using rbcsim::ibm::InterpolationStencil;
using rbcsim::ibm::node_count;
using rbcsim::ibm::node_index;

// A per-node vector field in the lattice's SoA layout.
struct NodeField {
  std::vector<double> x, y, z;
  explicit NodeField(std::size_t nodes) : x(nodes, 0.0), y(nodes, 0.0), z(nodes, 0.0) {}
  Vec3 at(std::size_t node) const { return Vec3(x[node], y[node], z[node]); }
  void set(std::size_t node, const Vec3& value) {
    x[node] = value.x();
    y[node] = value.y();
    z[node] = value.z();
  }
};

// A test geometry: a grid, its solid mask (empty = none) and where points may be placed
// (a box [low, high] in lattice coordinates).
struct Scene {
  std::string name;
  GridView grid;
  std::vector<std::uint8_t> solid;
  Vec3 low, high;
  const std::uint8_t* mask() const { return solid.empty() ? nullptr : solid.data(); }
};

// Fully periodic; points anywhere, also outside the box (they wrap).
Scene periodic_box() {
  return {"periodic", {12, 10, 8, true, true, true}, {}, Vec3(-2, -2, -2), Vec3(14, 12, 10)};
}

// A channel: periodic in x and y, solid walls on the planes k = 0 and k = nz - 1 plus a solid
// post; points up to half a spacing from the wall planes and inside the post's neighbourhood, so
// many stencils lose solid nodes.
Scene walled_channel() {
  Scene scene{"channel", {12, 10, 9, true, true, false}, {}, Vec3(0, 0, 0.5), Vec3(12, 10, 7.5)};
  scene.solid.assign(node_count(scene.grid), 0);
  for (int k = 0; k < scene.grid.nz; ++k) {
    for (int j = 0; j < scene.grid.ny; ++j) {
      for (int i = 0; i < scene.grid.nx; ++i) {
        const bool wall = k == 0 || k == scene.grid.nz - 1;
        const bool post = (i == 5 || i == 6) && j == 4;
        scene.solid[node_index(scene.grid, i, j, k)] = (wall || post) ? 1 : 0;
      }
    }
  }
  return scene;
}

// No periodic axis: points up to the faces, so stencils lose nodes outside the grid.
Scene closed_box() {
  return {"closed", {9, 8, 7, false, false, false}, {}, Vec3(0, 0, 0), Vec3(8, 7, 6)};
}

std::vector<Vec3> random_vectors(std::size_t count, const Vec3& low, const Vec3& high,
                                 std::mt19937_64& generator) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> vectors;
  for (std::size_t n = 0; n < count; ++n) {
    vectors.push_back(low + (high - low).cwiseProduct(rbcsim::random_vec3(unit, generator)));
  }
  return vectors;
}

// Random points in the scene's box with random forces, a random node velocity field, and the
// stencil of the points. (The post is one node thick, so every point keeps fluid nodes in reach.)
struct Case {
  Scene scene;
  std::vector<Vec3> positions, forces;
  NodeField velocity;
  InterpolationStencil stencil;

  Case(Scene scene_in, const DeltaKernel& kernel, std::size_t points)
      : scene(std::move(scene_in)), velocity(node_count(scene.grid)) {
    std::mt19937_64 generator(12345);
    positions = random_vectors(points, scene.low, scene.high, generator);
    forces = random_vectors(points, Vec3(-1, -1, -1), Vec3(1, 1, 1), generator);
    const auto node_values =
        random_vectors(node_count(scene.grid), Vec3(-1, -1, -1), Vec3(1, 1, 1), generator);
    for (std::size_t node = 0; node < node_values.size(); ++node) {
      velocity.set(node, node_values[node]);
    }
    stencil.build(kernel, scene.grid, positions, scene.mask());
  }

  NodeField spread() const {
    NodeField density(node_count(scene.grid));
    rbcsim::ibm::spread_forces(stencil, forces, scene.grid, density.x.data(), density.y.data(),
                               density.z.data());
    return density;
  }

  std::vector<Vec3> interpolate(const NodeField& field) const {
    std::vector<Vec3> velocities(positions.size());
    rbcsim::ibm::interpolate_velocity(stencil, scene.grid, field.x.data(), field.y.data(),
                                      field.z.data(), velocities);
    return velocities;
  }
};

Vec3 total(const NodeField& field) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t node = 0; node < field.x.size(); ++node) sum += field.at(node);
  return sum;
}

Scene scene_named(const std::string& name) {
  for (const auto& scene : {periodic_box(), walled_channel(), closed_box()}) {
    if (scene.name == name) return scene;
  }
  throw std::invalid_argument("no test scene " + name);
}

// Parameters: kernel name, scene name.
class KernelAndScene : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {
 protected:
  const DeltaKernel& kernel() const { return find_delta_kernel(std::get<0>(GetParam())); }
  Case make_case(std::size_t points = 300) const {
    return Case(scene_named(std::get<1>(GetParam())), kernel(), points);
  }
};

TEST_P(KernelAndScene, SpreadForceAddsUpToThePointForces) {
  const Case test = make_case();
  Vec3 point_total = Vec3::Zero();
  double magnitude = 0.0;
  for (const auto& force : test.forces) {
    point_total += force;
    magnitude += force.lpNorm<1>();
  }
  // Round-off only: each of the ~300 * 64 additions may lose an ulp of the running magnitude.
  EXPECT_LT((total(test.spread()) - point_total).lpNorm<Eigen::Infinity>(), 1e-13 * magnitude);
}

TEST_P(KernelAndScene, SpreadPutsNothingOnSolidNodes) {
  const Case test = make_case();
  const NodeField density = test.spread();
  for (std::size_t node = 0; node < test.scene.solid.size(); ++node) {
    if (test.scene.solid[node] != 0) {
      ASSERT_TRUE(density.at(node).isZero(0.0)) << node;
    }
  }
}

TEST_P(KernelAndScene, InterpolatesAUniformFieldExactly) {
  const Case test = make_case();
  const Vec3 uniform(0.03, -0.02, 0.01);
  NodeField field(node_count(test.scene.grid));
  for (std::size_t node = 0; node < field.x.size(); ++node) field.set(node, uniform);
  // Round-off only: up to 64 weights, each sum within a few ulp of 1.
  for (const auto& velocity : test.interpolate(field)) {
    EXPECT_LT((velocity - uniform).lpNorm<Eigen::Infinity>(), 1e-14 * uniform.norm());
  }
}

TEST_P(KernelAndScene, SpreadingIsTheAdjointOfInterpolation) {
  const Case test = make_case();
  const NodeField density = test.spread();
  const auto interpolated = test.interpolate(test.velocity);
  double grid_side = 0.0, point_side = 0.0, magnitude = 0.0;
  for (std::size_t node = 0; node < density.x.size(); ++node) {
    grid_side += test.velocity.at(node).dot(density.at(node));
  }
  for (std::size_t point = 0; point < test.forces.size(); ++point) {
    point_side += interpolated[point].dot(test.forces[point]);
    magnitude += interpolated[point].cwiseAbs().dot(test.forces[point].cwiseAbs());
  }
  // Both sides are sums of the same products in another order: round-off of ~1000 terms.
  EXPECT_NEAR(grid_side, point_side, 1e-13 * magnitude);
}

TEST_P(KernelAndScene, MatchesThePlainReference) {
  const Case test = make_case();
  NodeField reference_density(node_count(test.scene.grid));
  rbcsim::ibm::reference::spread_forces(kernel(), test.scene.grid, test.scene.mask(),
                                        test.positions, test.forces, reference_density.x.data(),
                                        reference_density.y.data(), reference_density.z.data());
  const NodeField density = test.spread();
  for (std::size_t node = 0; node < density.x.size(); ++node) {
    ASSERT_LT((density.at(node) - reference_density.at(node)).lpNorm<Eigen::Infinity>(), 1e-14)
        << node;
  }
  std::vector<Vec3> reference_velocities(test.positions.size());
  rbcsim::ibm::reference::interpolate_velocity(
      kernel(), test.scene.grid, test.scene.mask(), test.positions, test.velocity.x.data(),
      test.velocity.y.data(), test.velocity.z.data(), reference_velocities);
  const auto velocities = test.interpolate(test.velocity);
  for (std::size_t point = 0; point < velocities.size(); ++point) {
    ASSERT_LT((velocities[point] - reference_velocities[point]).lpNorm<Eigen::Infinity>(), 1e-14)
        << point;
  }
}

TEST_P(KernelAndScene, ResultsDoNotDependOnTheThreadCount) {
  // Many points in a small grid, so that nodes get many contributions and stencils straddle the
  // threads' node ranges; and enough work that the two threads overlap in time (with a few
  // thousand points the first thread finishes before the second starts, and an order-dependent
  // spread, with atomics or per-thread buffers, passed this test by luck).
  const int previous_threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Case one_thread_case = make_case(20000);
  const NodeField one_thread = one_thread_case.spread();
  const auto one_thread_velocities = one_thread_case.interpolate(one_thread_case.velocity);
  omp_set_num_threads(2);
  const Case two_thread_case = make_case(20000);
  const NodeField two_threads = two_thread_case.spread();
  const auto two_thread_velocities = two_thread_case.interpolate(two_thread_case.velocity);
  omp_set_num_threads(previous_threads);
  // Bit for bit.
  EXPECT_EQ(one_thread.x, two_threads.x);
  EXPECT_EQ(one_thread.y, two_threads.y);
  EXPECT_EQ(one_thread.z, two_threads.z);
  EXPECT_EQ(one_thread_velocities, two_thread_velocities);
}

TEST_P(KernelAndScene, SpreadingSeveralSourcesAtOnceEqualsSpreadingThemInTurn) {
  // Three overlapping point sets (cells) spread in one parallel region must give, bit for bit,
  // what spreading them one after the other gives: the order every node receives its terms in.
  const int previous_threads = omp_get_max_threads();
  omp_set_num_threads(2);
  const Case first = make_case(3000), second = make_case(2000), third = make_case(1000);
  NodeField in_turn(node_count(first.scene.grid));
  for (const Case* source : {&first, &second, &third}) {
    rbcsim::ibm::spread_forces(source->stencil, source->forces, first.scene.grid,
                               in_turn.x.data(), in_turn.y.data(), in_turn.z.data());
  }
  const std::vector<rbcsim::ibm::SpreadSource> sources{{&first.stencil, first.forces},
                                          {&second.stencil, second.forces},
                                          {&third.stencil, third.forces}};
  NodeField at_once(node_count(first.scene.grid));
  rbcsim::ibm::spread_forces(sources, first.scene.grid, at_once.x.data(), at_once.y.data(),
                             at_once.z.data());
  omp_set_num_threads(previous_threads);
  EXPECT_EQ(in_turn.x, at_once.x);
  EXPECT_EQ(in_turn.y, at_once.y);
  EXPECT_EQ(in_turn.z, at_once.z);
}

INSTANTIATE_TEST_SUITE_P(All, KernelAndScene,
                         ::testing::Combine(::testing::Values("phi2", "phi3", "phi4"),
                                            ::testing::Values("periodic", "channel", "closed")),
                         [](const auto& test_info) {
                           return std::get<0>(test_info.param) + "_" + std::get<1>(test_info.param);
                         });

// Zeroth and first moment conditions hold for every kernel, so a linear field is reproduced
// exactly wherever the whole support lies inside the fluid.
class LinearFieldKernel : public ::testing::TestWithParam<std::string> {};

TEST_P(LinearFieldKernel, InterpolatesALinearFieldExactlyAwayFromBoundaries) {
  const Scene scene{"closed", {12, 11, 10, false, false, false}, {}, Vec3(2, 2, 2), Vec3(9, 8, 7)};
  const Case test(scene, find_delta_kernel(GetParam()), 200);
  const Vec3 offset(0.01, -0.02, 0.005);
  Eigen::Matrix3d gradient;
  gradient << 0.001, -0.002, 0.003, 0.0005, 0.002, -0.001, -0.003, 0.0015, 0.0025;
  NodeField field(node_count(scene.grid));
  for (int k = 0; k < scene.grid.nz; ++k) {
    for (int j = 0; j < scene.grid.ny; ++j) {
      for (int i = 0; i < scene.grid.nx; ++i) {
        field.set(node_index(scene.grid, i, j, k), offset + gradient * Vec3(i, j, k));
      }
    }
  }
  const auto velocities = test.interpolate(field);
  // Round-off only: up to 64 terms of size <= 0.06.
  for (std::size_t point = 0; point < velocities.size(); ++point) {
    const Vec3 exact = offset + gradient * test.positions[point];
    EXPECT_LT((velocities[point] - exact).lpNorm<Eigen::Infinity>(), 1e-15) << point;
  }
}

INSTANTIATE_TEST_SUITE_P(Kernels, LinearFieldKernel, ::testing::Values("phi2", "phi3", "phi4"),
                         [](const auto& test_info) { return test_info.param; });

TEST(Transfer, AStencilBuiltForAnotherGridOrPointCountIsRejected) {
  const Case test(periodic_box(), find_delta_kernel("phi2"), 4);
  NodeField field(node_count(test.scene.grid));
  const GridView other_grid{12, 10, 8, true, true, false};
  const std::vector<Vec3> too_few_forces(3, Vec3::Zero());
  std::vector<Vec3> velocities(4);
  EXPECT_THROW(rbcsim::ibm::spread_forces(test.stencil, test.forces, other_grid, field.x.data(),
                                          field.y.data(), field.z.data()),
               std::invalid_argument);
  EXPECT_THROW(rbcsim::ibm::spread_forces(test.stencil, too_few_forces, test.scene.grid,
                                          field.x.data(), field.y.data(), field.z.data()),
               std::invalid_argument);
  EXPECT_THROW(rbcsim::ibm::interpolate_velocity(test.stencil, other_grid, field.x.data(),
                                                 field.y.data(), field.z.data(), velocities),
               std::invalid_argument);
}

}  // namespace
