// The drag on the membrane's sub-spacing modes (coupling/sub_spacing_drag.hpp,
// `ibm.sub_spacing_drag`): as a kernel, it moves a vertex at the Stokes drag of the shortest mode
// (along its normal at half the rate) for a force its neighbours do not share, and leaves forces
// shared along the membrane to the lattice; in a coupled run it relaxes a pattern of triangle areas
// finer than the lattice, which the immersed boundary alone does not, without moving the cell or
// changing its volume.
#include "coupling/sub_spacing_drag.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "cases/json_values.hpp"
#include "common/errors.hpp"
#include "coupling/coupled_simulation.hpp"
#include "coupling_fixtures.hpp"
#include "mesh/geometry.hpp"
#include "mesh/topology.hpp"

namespace rbcsim::coupling::sub_spacing_drag_test {
namespace {

using testing::periodic_fluid;
using testing::plasma_units;
using testing::sphere_mesh;

struct VertexMeasures {
  std::vector<Vec3> normals;
  std::vector<double> areas;
  std::vector<double> mean_edge_lengths;
};

// Area-weighted normals, a third of the triangles' areas and the mean edge length, by hand.
VertexMeasures measure(const mesh::TriangleMesh& mesh, const mesh::MeshTopology& topology) {
  VertexMeasures m{std::vector<Vec3>(mesh.vertex_count(), Vec3::Zero()),
                   std::vector<double>(mesh.vertex_count(), 0.0),
                   std::vector<double>(mesh.vertex_count(), 0.0)};
  const auto& x = mesh.positions_um;
  for (const auto& t : mesh.triangles) {
    const Vec3 twice_area = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
    for (const int corner : t) {
      m.normals[corner] += twice_area;
      m.areas[corner] += twice_area.norm() / 6.0;
    }
  }
  std::vector<int> degree(mesh.vertex_count(), 0);
  for (const auto& edge : topology.edges()) {
    const double length = (x[edge.vertex0] - x[edge.vertex1]).norm();
    for (const int v : {edge.vertex0, edge.vertex1}) {
      m.mean_edge_lengths[v] += length;
      ++degree[v];
    }
  }
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    m.normals[v].normalize();
    m.mean_edge_lengths[v] /= degree[v];
  }
  return m;
}

// An off-centre ellipsoid, so that no symmetry hides an error.
mesh::TriangleMesh ellipsoid(int level) {
  auto mesh = sphere_mesh(level, 1.0, Vec3::Zero());
  for (Vec3& x : mesh.positions_um) x = Vec3(3.9 * x.x() + 1.0, 3.5 * x.y() - 2.0, 1.4 * x.z());
  return mesh;
}

constexpr double kViscositySum = 0.7;  // eta_out + eta_in, any unit

TEST(SubSpacingDrag, AForceEveryVertexSharesMovesNothing) {
  const auto mesh = ellipsoid(3);
  const auto topology = mesh::MeshTopology::build(mesh);
  SubSpacingDrag drag(mesh.triangles, topology);
  const std::vector<Vec3> forces(mesh.vertex_count(), Vec3(3.0, -1.0, 2.0));
  std::vector<Vec3> velocities(mesh.vertex_count(), Vec3::Zero());
  drag.add_velocities(mesh.positions_um, forces, kViscositySum, velocities);
  for (std::size_t v = 0; v < velocities.size(); ++v) {
    EXPECT_LT(velocities[v].norm(), 1e-14) << "vertex " << v;
  }
}

TEST(SubSpacingDrag, MovesAVertexAlongItsNormalAtHalfItsRateAlongTheMembrane) {
  // Stokes: a traction along the membrane meets eta q on each side, one along its normal 2 eta q.
  const auto mesh = ellipsoid(3);
  const auto topology = mesh::MeshTopology::build(mesh);
  const auto measures = measure(mesh, topology);
  SubSpacingDrag drag(mesh.triangles, topology);
  std::mt19937 random(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Vec3> forces(mesh.vertex_count());
  for (Vec3& f : forces) f = Vec3(normal(random), normal(random), normal(random));
  std::vector<Vec3> velocities(mesh.vertex_count(), Vec3::Zero());
  drag.add_velocities(mesh.positions_um, forces, kViscositySum, velocities);
  std::vector<Vec3> neighbour_sum(mesh.vertex_count(), Vec3::Zero());
  std::vector<int> degree(mesh.vertex_count(), 0);
  for (const auto& edge : topology.edges()) {
    neighbour_sum[edge.vertex0] += forces[edge.vertex1];
    neighbour_sum[edge.vertex1] += forces[edge.vertex0];
    ++degree[edge.vertex0];
    ++degree[edge.vertex1];
  }
  for (std::size_t v = 0; v < velocities.size(); ++v) {
    const Vec3 unshared = forces[v] - neighbour_sum[v] / degree[v];
    const Vec3& n = measures.normals[v];
    const double drag_v =
        kViscositySum * std::numbers::pi / measures.mean_edge_lengths[v] * measures.areas[v];
    const Vec3 along = (unshared - unshared.dot(n) * n) / drag_v;
    const Vec3 across = 0.5 * unshared.dot(n) * n / drag_v;
    EXPECT_LT((velocities[v] - along - across).norm(), 1e-12 * (along + across).norm())
        << "vertex " << v;
  }
}

TEST(SubSpacingDrag, OneVertexPushedAloneMovesAtTheStokesDragOfTheShortestMode) {
  // A force on one vertex alone is the finest pattern there is: it moves at F / ((eta_out +
  // eta_in) q A), q = pi / l, and each neighbour, whose mean it enters once in its degree, the
  // other way by that share; nobody else moves. Velocities already there are added to.
  const auto mesh = ellipsoid(3);
  const auto topology = mesh::MeshTopology::build(mesh);
  const auto measures = measure(mesh, topology);
  SubSpacingDrag drag(mesh.triangles, topology);
  const std::size_t pushed = 100;
  const Vec3& n = measures.normals[pushed];
  const Vec3 tangential = (Vec3(1.0, 2.0, -0.5) - Vec3(1.0, 2.0, -0.5).dot(n) * n) * 4.0;
  std::vector<Vec3> forces(mesh.vertex_count(), Vec3::Zero());
  forces[pushed] = tangential + 3.0 * n;  // the normal part moves at half the rate
  std::vector<Vec3> velocities(mesh.vertex_count(), Vec3(0.5, 0.0, 0.0));
  drag.add_velocities(mesh.positions_um, forces, kViscositySum, velocities);
  const auto drag_of = [&](std::size_t v) {
    return kViscositySum * std::numbers::pi / measures.mean_edge_lengths[v] * measures.areas[v];
  };
  const Vec3 expected_pushed = (tangential + 1.5 * n) / drag_of(pushed);
  EXPECT_LT((velocities[pushed] - Vec3(0.5, 0.0, 0.0) - expected_pushed).norm(),
            1e-12 * expected_pushed.norm());
  std::vector<int> degree(mesh.vertex_count(), 0);
  std::vector<bool> neighbour(mesh.vertex_count(), false);
  for (const auto& edge : topology.edges()) {
    ++degree[edge.vertex0];
    ++degree[edge.vertex1];
    if (static_cast<std::size_t>(edge.vertex0) == pushed) neighbour[edge.vertex1] = true;
    if (static_cast<std::size_t>(edge.vertex1) == pushed) neighbour[edge.vertex0] = true;
  }
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (v == pushed) continue;
    Vec3 expected = Vec3::Zero();
    if (neighbour[v]) {
      const Vec3 share = -forces[pushed] / degree[v];
      expected = (share - 0.5 * share.dot(measures.normals[v]) * measures.normals[v]) / drag_of(v);
    }
    EXPECT_LT((velocities[v] - Vec3(0.5, 0.0, 0.0) - expected).norm(), 1e-12) << "vertex " << v;
  }
}

// The largest velocity the drag gives a force that turns over the whole of a sphere of `level`
// (a rigid rotation's, tangential), over the largest it would give that force on one vertex
// pushed alone.
double smooth_force_leak(int level) {
  const Vec3 centre(0.5, -1.0, 2.0);
  const auto mesh = sphere_mesh(level, 3.0, centre);
  const auto topology = mesh::MeshTopology::build(mesh);
  const auto measures = measure(mesh, topology);
  SubSpacingDrag drag(mesh.triangles, topology);
  const Vec3 omega(0.3, -0.2, 1.0);
  std::vector<Vec3> forces(mesh.vertex_count());
  for (std::size_t v = 0; v < forces.size(); ++v) {
    forces[v] = omega.cross(mesh.positions_um[v] - centre);
  }
  std::vector<Vec3> velocities(mesh.vertex_count(), Vec3::Zero());
  drag.add_velocities(mesh.positions_um, forces, kViscositySum, velocities);
  // Against the largest single-vertex response: near the rotation's poles the force vanishes
  // but the curvature's part of the difference does not.
  double largest_velocity = 0.0, largest_alone = 0.0;
  for (std::size_t v = 0; v < forces.size(); ++v) {
    largest_velocity = std::max(largest_velocity, velocities[v].norm());
    largest_alone = std::max(
        largest_alone, forces[v].norm() / (kViscositySum * std::numbers::pi /
                                           measures.mean_edge_lengths[v] * measures.areas[v]));
  }
  return largest_velocity / largest_alone;
}

TEST(SubSpacingDrag, ASmoothForceIsLeftToTheLattice) {
  // A force varying over the whole cell is what the lattice resolves. Its neighbours' mean
  // differs from a vertex's own by the ring's curvature, O((l / R)^2), and by the icosphere's
  // irregular rings, O(l / R): under 3 % of the largest single-vertex response at level 3
  // (l / R ~ 0.12), and at least halved with edges half as long (level 4).
  const double level3 = smooth_force_leak(3);
  const double level4 = smooth_force_leak(4);
  EXPECT_LT(level3, 0.03);
  EXPECT_LT(level4, 0.6 * level3);
}

TEST(SubSpacingDrag, FindsTheRateOfItsFastestModeBetweenItsBounds) {
  // Every vertex tied to its place by a spring k: the stiffness is k, and the drag relaxes a
  // pattern at k times its own largest gain, which lies between that of one vertex pushed alone
  // (1 / drag_v) and twice it (a neighbours' mean differs from a vertex's by at most twice the
  // largest force).
  const auto mesh = ellipsoid(3);
  const auto topology = mesh::MeshTopology::build(mesh);
  const auto measures = measure(mesh, topology);
  SubSpacingDrag drag(mesh.triangles, topology);
  const double k = 2.5;
  const ForceFunction springs = [&](std::span<const Vec3> x, std::span<Vec3> f) {
    for (std::size_t v = 0; v < x.size(); ++v) f[v] = -k * (x[v] - mesh.positions_um[v]);
  };
  double largest_gain = 0.0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    largest_gain =
        std::max(largest_gain, 1.0 / (kViscositySum * std::numbers::pi /
                                      measures.mean_edge_lengths[v] * measures.areas[v]));
  }
  const double rate = fastest_drag_rate(drag, mesh.positions_um, springs, kViscositySum);
  EXPECT_GE(rate, k * largest_gain);
  EXPECT_LE(rate, 2.0 * k * largest_gain);
}

TEST(SubSpacingDrag, RefusesArraysOfAnotherLengthAndANonPositiveViscosity) {
  const auto mesh = ellipsoid(1);
  const auto topology = mesh::MeshTopology::build(mesh);
  SubSpacingDrag drag(mesh.triangles, topology);
  std::vector<Vec3> forces(mesh.vertex_count(), Vec3::Zero());
  std::vector<Vec3> velocities(mesh.vertex_count() - 1, Vec3::Zero());
  EXPECT_THROW(drag.add_velocities(mesh.positions_um, forces, 1.0, velocities),
               std::invalid_argument);
  velocities.resize(mesh.vertex_count());
  EXPECT_THROW(drag.add_velocities(mesh.positions_um, forces, 0.0, velocities),
               std::invalid_argument);
}

// The root mean square of the triangles' relative area changes against `reference`.
double area_change_rms(std::span<const Vec3> positions, std::span<const Vec3> reference,
                       std::span<const mesh::Triangle> triangles) {
  double sum = 0.0;
  for (const auto& t : triangles) {
    const double area =
        (positions[t[1]] - positions[t[0]]).cross(positions[t[2]] - positions[t[0]]).norm();
    const double rest =
        (reference[t[1]] - reference[t[0]]).cross(reference[t[2]] - reference[t[0]]).norm();
    sum += (area / rest - 1.0) * (area / rest - 1.0);
  }
  return std::sqrt(sum / static_cast<double>(triangles.size()));
}

struct Relaxation {
  double start_rms, end_rms;
  double centroid_shift_lu, volume_change;
};

// A capsule of 2562 vertices with edges of half a spacing (the paper's pairing), its vertices
// moved along the membrane by a random pattern of up to 0.02 dx, in plasma at rest: `steps` coupled
// steps with and without the drag.
Relaxation relax_sub_spacing_pattern(bool with_drag, int steps) {
  const Vec3 centre_um(6.1, 5.9, 6.05);
  const auto sphere = sphere_mesh(4, 3.6, centre_um);
  const auto topology = mesh::MeshTopology::build(sphere);
  const auto measures = measure(sphere, topology);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Vec3> start_um(sphere.positions_um);
  for (std::size_t v = 0; v < start_um.size(); ++v) {
    const Vec3 step(uniform(random), uniform(random), uniform(random));
    const Vec3& n = measures.normals[v];
    start_um[v] += 0.01 * (step - step.dot(n) * n);
  }
  membrane::MembraneParameters parameters = testing::capsule_parameters(20.0);
  parameters.forces.push_back("local_area");
  // The pattern's forces do not relax without the drag: no cap, so that both runs see the same
  // force law (a cap hit would stop the run, by design).
  parameters.vertex_force_cap_pN = std::numeric_limits<double>::infinity();
  CouplingParameters coupling;
  coupling.sub_spacing_drag = with_drag;
  CoupledSimulation simulation(periodic_fluid(24, 24, 24), plasma_units(), coupling);
  simulation.add_cell(membrane::MembraneModel(sphere, parameters), start_um);
  const Cell& cell = simulation.cell(0);
  const std::vector<Vec3> rest_lu = [&] {
    std::vector<Vec3> rest(sphere.vertex_count());
    for (std::size_t v = 0; v < rest.size(); ++v) {
      rest[v] = simulation.frame().to_lattice(sphere.positions_um[v]);
    }
    return rest;
  }();
  const Vec3 start_centroid = cell.centroid_lu();
  const double start_volume = mesh::enclosed_volume_um3(
      {std::vector<Vec3>(cell.positions_lu().begin(), cell.positions_lu().end()),
       sphere.triangles});
  Relaxation result{area_change_rms(cell.positions_lu(), rest_lu, sphere.triangles), 0.0, 0.0, 0.0};
  for (int step = 0; step < steps; ++step) simulation.step();
  result.end_rms = area_change_rms(cell.positions_lu(), rest_lu, sphere.triangles);
  result.centroid_shift_lu = (cell.centroid_lu() - start_centroid).norm();
  result.volume_change = mesh::enclosed_volume_um3({std::vector<Vec3>(cell.positions_lu().begin(),
                                                                      cell.positions_lu().end()),
                                                    sphere.triangles}) /
                             start_volume -
                         1.0;
  return result;
}

TEST(SubSpacingDrag, RelaxesTriangleAreasFinerThanTheLatticeWhereTheFluidDoesNot) {
  // Without the drag the fluid carries the pattern's forces only as far as the phi2 kernel
  // leaves them uncancelled; with it each triangle relaxes at its own rate (local_area's
  // 500 uN/m over the drag of the shortest mode: ~0.1 per step here). Measured (December
  // 2026): the rms of 4.3 % falls to 0.95 of itself without and to 0.09 with the drag in 200
  // steps; the bounds leave room for another kernel or mesh, not for a drag that does nothing.
  const Relaxation without = relax_sub_spacing_pattern(false, 200);
  const Relaxation with = relax_sub_spacing_pattern(true, 200);
  ASSERT_GT(without.start_rms, 0.01);
  EXPECT_EQ(with.start_rms, without.start_rms);
  EXPECT_GT(without.end_rms, 0.5 * without.start_rms);
  EXPECT_LT(with.end_rms, 0.2 * with.start_rms);
  // Summing to almost nothing, it neither moves the cell nor changes its volume beyond what the
  // relaxing flow itself does (3e-5 dx and 1e-6 measured).
  EXPECT_LT(with.centroid_shift_lu, 1e-3);
  EXPECT_LT(std::abs(with.volume_change), 1e-3);
}

// What the runs write to result.json (`sub_spacing_drag`): the fastest rate over the cells and
// how many had their drag raised, which a membrane a thousand times stiffer than a soft capsule
// must be (the rate grows with the stiffness; the soft one's is below the limit).
TEST(SubSpacingDrag, SummarisesTheFastestRateAndTheCellsWhoseDragWasRaised) {
  const auto soft = testing::capsule_parameters(20.0);
  const auto stiff = testing::capsule_parameters(20000.0);
  double stiff_rate = 0.0;
  const auto summary_of = [&](bool with_drag) {
    CouplingParameters coupling;
    coupling.sub_spacing_drag = with_drag;
    CoupledSimulation simulation(periodic_fluid(40, 24, 24), plasma_units(), coupling);
    const auto left = sphere_mesh(3, 3.6, Vec3(5.0, 6.0, 6.0));
    const auto right = sphere_mesh(3, 3.6, Vec3(14.0, 6.0, 6.0));
    simulation.add_cell(membrane::MembraneModel(left, soft), left.positions_um);
    simulation.add_cell(membrane::MembraneModel(right, stiff), right.positions_um);
    const double soft_rate = simulation.cell(0).sub_spacing_drag_rate();
    stiff_rate = simulation.cell(1).sub_spacing_drag_rate();
    if (with_drag) {
      EXPECT_GT(soft_rate, 0.0);
      EXPECT_LT(soft_rate, Cell::kMaxDragRatePerStep);
      EXPECT_GT(stiff_rate, Cell::kMaxDragRatePerStep);
    }
    return simulation.sub_spacing_drag_summary();
  };
  const SubSpacingDragSummary off = summary_of(false);
  EXPECT_FALSE(off.on);
  EXPECT_EQ(off.fastest_rate_per_step, 0.0);
  EXPECT_EQ(off.raised_cells, 0u);
  EXPECT_EQ(off.viscosity_raised_by, 1.0);
  const SubSpacingDragSummary on = summary_of(true);
  EXPECT_TRUE(on.on);
  EXPECT_EQ(on.fastest_rate_per_step, stiff_rate);
  EXPECT_EQ(on.raised_cells, 1u);
  EXPECT_DOUBLE_EQ(on.viscosity_raised_by, stiff_rate / Cell::kMaxDragRatePerStep);
}

// A finished rate's point.json keeps the summary (a resumed sweep reports it): it reads back as
// written, and a hand-broken entry is one InputError naming the file, not the JSON library's.
TEST(SubSpacingDrag, SummaryReadsBackFromARecordAndABrokenOneNamesItsFile) {
  const SubSpacingDragSummary written{
      .on = true, .fastest_rate_per_step = 2.5, .raised_cells = 3, .viscosity_raised_by = 2.5};
  const nlohmann::json record = cases::sub_spacing_drag_json(written);
  const auto read = cases::sub_spacing_drag_from_json(record, "point.json");
  EXPECT_TRUE(read.on);
  EXPECT_EQ(read.fastest_rate_per_step, 2.5);
  EXPECT_EQ(read.raised_cells, 3u);
  EXPECT_EQ(read.viscosity_raised_by, 2.5);
  EXPECT_FALSE(cases::sub_spacing_drag_from_json(nullptr, "point.json").on);
  for (const char* broken : {R"({"fastest_rate_per_step": 2.5, "raised_cells": 3})",
                             R"({"fastest_rate_per_step": "fast", "raised_cells": 3,
                                 "viscosity_raised_by": 1})",
                             R"({"fastest_rate_per_step": 2.5, "raised_cells": 1.5,
                                 "viscosity_raised_by": 1})",
                             "[1, 2]"}) {
    SCOPED_TRACE(broken);
    try {
      (void)cases::sub_spacing_drag_from_json(nlohmann::json::parse(broken), "point.json");
      ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("point.json"), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace rbcsim::coupling::sub_spacing_drag_test
