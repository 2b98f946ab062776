// The surface contact law (contact/surface_repulsion.hpp): the nearest point of a triangle, and
// two facing membrane patches whose vertices are offset sideways, the arrangement in which two
// cells of a 10 um tube run passed through each other under the vertex-pair law. Vertex pairs lose
// their normal push as the gap closes; the surface law's grows, pushes a vertex that is already
// through back out, conserves momentum and does not depend on the thread count.
#include "contact/surface_repulsion.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "common/thread_count_scope.hpp"

namespace rbcsim::contact {
namespace {

// Two square patches of n x n vertices 0.5 um apart: A in the plane z = 0, its outside +z; B at
// z = gap, its outside -z (facing A), shifted by (0.25, 0.25) um so that no vertex faces another.
struct Patches {
  std::vector<Vec3> positions_um;
  std::vector<std::uint32_t> owner;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> offsets, vertex_triangles;
  std::size_t per_patch = 0;

  ContactSurfaces surfaces() const { return {triangles, offsets, vertex_triangles}; }
  // Each vertex's triangles (offsets, vertex_triangles) from the triangles.
  void index_vertex_triangles() {
    std::vector<std::vector<std::uint32_t>> of_vertex(positions_um.size());
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
      for (const auto v : triangles[t]) of_vertex[v].push_back(t);
    }
    offsets.assign(1, 0);
    vertex_triangles.clear();
    for (const auto& row : of_vertex) {
      vertex_triangles.insert(vertex_triangles.end(), row.begin(), row.end());
      offsets.push_back(static_cast<std::uint32_t>(vertex_triangles.size()));
    }
  }
};

Patches facing_patches(double gap_um, int n = 9) {
  Patches p;
  p.per_patch = static_cast<std::size_t>(n * n);
  for (std::uint32_t patch = 0; patch < 2; ++patch) {
    const auto base = static_cast<std::uint32_t>(p.positions_um.size());
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        p.positions_um.push_back(patch == 0 ? Vec3(0.5 * i, 0.5 * j, 0.0)
                                            : Vec3(0.5 * i + 0.25, 0.5 * j + 0.25, gap_um));
        p.owner.push_back(patch);
      }
    }
    for (int i = 0; i + 1 < n; ++i) {
      for (int j = 0; j + 1 < n; ++j) {
        const auto at = [&](int a, int b) { return base + static_cast<std::uint32_t>(a * n + b); };
        // Counter-clockwise seen from +z for A (outside +z), clockwise for B (outside -z).
        std::array<std::array<std::uint32_t, 3>, 2> pair{
            {{at(i, j), at(i + 1, j), at(i + 1, j + 1)},
             {at(i, j), at(i + 1, j + 1), at(i, j + 1)}}};
        for (auto t : pair) {
          if (patch == 1) std::swap(t[1], t[2]);
          p.triangles.push_back(t);
        }
      }
    }
  }
  p.index_vertex_triangles();
  return p;
}

struct Push {
  double normal_on_a_pN = 0.0;  // the total push on A along -z (away from B)
  Vec3 net_pN = Vec3::Zero();
  double magnitude_pN = 0.0;
  std::vector<Vec3> forces_pN;
  ContactStatistics statistics;
};

Push push_of(const Patches& p, ContactLaw law,
             double cap_pN = std::numeric_limits<double>::infinity()) {
  const ContactParameters parameters{5.0, 0.75, law, cap_pN};
  Push push;
  push.forces_pN.assign(p.positions_um.size(), Vec3::Zero());
  ContactWorkspace workspace;
  if (law == ContactLaw::surface) {
    push.statistics = add_surface_contact_forces(p.positions_um, p.owner, p.surfaces(), parameters,
                                                 {}, push.forces_pN, workspace);
  } else {
    push.statistics =
        add_cell_contact_forces(p.positions_um, p.owner, parameters, {}, push.forces_pN, workspace);
  }
  for (std::size_t v = 0; v < push.forces_pN.size(); ++v) {
    if (v < p.per_patch) push.normal_on_a_pN -= push.forces_pN[v].z();
    push.net_pN += push.forces_pN[v];
    push.magnitude_pN += push.forces_pN[v].norm();
  }
  return push;
}

TEST(SurfaceContact, NearestPointOfATriangleIsTheNearestOfAllItsPoints) {
  std::mt19937 generator(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a(unit(generator), unit(generator), unit(generator));
    const Vec3 b(unit(generator), unit(generator), unit(generator));
    const Vec3 c(unit(generator), unit(generator), unit(generator));
    const Vec3 p(2.0 * unit(generator), 2.0 * unit(generator), 2.0 * unit(generator));
    const auto w = nearest_on_triangle(p, a, b, c);
    EXPECT_NEAR(w[0] + w[1] + w[2], 1.0, 1e-12);
    for (const double weight : w) EXPECT_GE(weight, -1e-12);
    const double found = (p - (w[0] * a + w[1] * b + w[2] * c)).norm();
    // Against every point of a barycentric grid of step 1/200: never farther, and within the
    // grid's resolution of the nearest of them.
    double sampled = 1e9;
    for (int i = 0; i <= 200; ++i) {
      for (int j = 0; i + j <= 200; ++j) {
        const double u = i / 200.0, v = j / 200.0;
        sampled = std::min(sampled, (p - ((1 - u - v) * a + u * b + v * c)).norm());
      }
    }
    EXPECT_LE(found, sampled + 1e-12) << trial;
    EXPECT_NEAR(found, sampled, 0.02) << trial;
  }
}

// As the patches close in, vertex pairs turn tangential: their normal push peaks and then falls
// towards zero at contact (no barrier). The surface law's grows all the way, as
// F_half (r / gap - 1)^2 per contact.
TEST(SurfaceContact, FacingPatchesArePushedApartHarderTheCloserTheyAre) {
  const std::vector<double> gaps{0.3, 0.2, 0.1, 0.05, 0.02, 0.005};
  std::vector<double> vertex, surface;
  for (const double gap : gaps) {
    const auto patches = facing_patches(gap);
    vertex.push_back(push_of(patches, ContactLaw::vertex).normal_on_a_pN);
    surface.push_back(push_of(patches, ContactLaw::surface).normal_on_a_pN);
  }
  for (std::size_t k = 1; k < gaps.size(); ++k) {
    SCOPED_TRACE(gaps[k]);
    EXPECT_GT(surface[k], surface[k - 1]);
  }
  EXPECT_LT(vertex.back(), 0.1 * vertex[2]);  // at 5 nm, a tenth of its push at 0.1 um
  EXPECT_GT(surface.back(), 100.0 * vertex.back());
  // Each of A's 81 vertices faces B's surface straight across (or just beyond its edge), and B's
  // 81 face A's: per contact F_half (r / gap - 1)^2, along z for those inside the other patch.
  const double per_contact = 5.0 * std::pow(0.75 / 0.1 - 1.0, 2);
  EXPECT_GT(surface[2], 100.0 * per_contact);
  EXPECT_LT(surface[2], 162.0 * per_contact * (1.0 + 1e-9));
}

// The cap holds each push at force_cap_pN where the law would exceed it, and counts it; pushes
// below the cap are untouched. At a 0.05 um gap the law asks 5 (0.75 / 0.05 - 1)^2 = 980 pN of
// each facing contact; at 0.3 um, 11.25 pN at most.
TEST(SurfaceContact, TheCapHoldsEachPushAtItAndCountsIt) {
  const double cap_pN = 50.0;
  const auto close = facing_patches(0.05);
  const auto capped = push_of(close, ContactLaw::surface, cap_pN);
  const auto free = push_of(close, ContactLaw::surface);
  EXPECT_EQ(free.statistics.capped_pushes, 0u);
  EXPECT_GE(capped.statistics.capped_pushes, 100u);
  EXPECT_LE(capped.statistics.capped_pushes, capped.statistics.pairs_in_range);
  // Each of at most 162 contacts pushes A away by at most the cap.
  EXPECT_LE(capped.normal_on_a_pN, 162.0 * cap_pN * (1.0 + 1e-9));
  EXPECT_GE(capped.normal_on_a_pN, 100.0 * cap_pN);
  EXPECT_GT(free.normal_on_a_pN, 10.0 * capped.normal_on_a_pN);
  EXPECT_LT(capped.net_pN.norm(), 1e-12 * capped.magnitude_pN);

  const auto apart = facing_patches(0.3);
  const auto below = push_of(apart, ContactLaw::surface, cap_pN);
  EXPECT_EQ(below.statistics.capped_pushes, 0u);
  EXPECT_EQ(below.forces_pN, push_of(apart, ContactLaw::surface).forces_pN);
}

// A vertex that is already through the other surface is pushed back out (the vertex pairs pull it
// further in once it has crossed between them).
TEST(SurfaceContact, AVertexThroughTheSurfaceIsPushedBackOut) {
  auto patches = facing_patches(0.2);
  const std::size_t middle = 4 * 9 + 4;
  patches.positions_um[middle].z() = 0.25;  // A's middle vertex 0.05 um beyond B, at z = 0.2
  const auto surface = push_of(patches, ContactLaw::surface);
  EXPECT_LT(surface.forces_pN[middle].z(), 0.0);
  const auto vertex = push_of(patches, ContactLaw::vertex);
  EXPECT_GT(vertex.forces_pN[middle].z(), 0.0);
}

// Beyond a sharp edge or corner the nearest point is shared by several faces, and a point outside
// can lie on the inner side of one of them (a regular tetrahedron's faces meet at 109.5 degrees):
// the side comes from the angle-weighted pseudo-normal, so such a vertex is pushed away from the
// other cell, never into it, whichever of the faces the search meets first.
TEST(SurfaceContact, AVertexBeyondAnEdgeOrCornerIsPushedAway) {
  // Cell 0: a regular tetrahedron (edges 2.8 um), its faces outward.
  const std::vector<Vec3> corners{Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  const std::vector<std::array<std::uint32_t, 3>> faces{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  const auto outward = [&](std::size_t f) {
    const auto& t = faces[f];
    return Vec3((corners[t[1]] - corners[t[0]]).cross(corners[t[2]] - corners[t[0]]).normalized());
  };
  // Outward normals: faces 0 and 1 share the edge 0-1; faces 0, 1 and 2 share corner 0.
  ASSERT_GT(outward(0).dot(Vec3(1, 1, -1)), 0.0);
  const auto push_at = [&](const Vec3& nearest, const Vec3& away) {
    Patches p;
    p.positions_um = corners;
    // Cell 1: the same tetrahedron, a third the size, turned so that its corner 0 points at
    // cell 0 from x (its faces still outward).
    const Vec3 x = nearest + 0.1 * away;
    const Eigen::Matrix3d turn =
        Eigen::Quaterniond::FromTwoVectors(corners[0], -away).toRotationMatrix();
    for (const Vec3& c : corners) p.positions_um.push_back(x + turn * ((c - corners[0]) / 3.0));
    p.owner = {0, 0, 0, 0, 1, 1, 1, 1};
    p.triangles = faces;
    for (const auto& f : faces) p.triangles.push_back({f[0] + 4, f[1] + 4, f[2] + 4});
    p.index_vertex_triangles();
    std::vector<Vec3> forces(8, Vec3::Zero());
    ContactWorkspace workspace;
    add_surface_contact_forces(p.positions_um, p.owner, p.surfaces(),
                               {5.0, 0.5, ContactLaw::surface}, {}, forces, workspace);
    return forces[4];
  };
  // The push the law gives at 0.1 um: x's own, at least (at the corner, the corner's push from
  // x's cell adds its reaction on x, in the same direction).
  const double push_pN = 5.0 * std::pow(0.5 / 0.1 - 1.0, 2) * (1.0 - 1e-9);
  const Vec3 edge_middle = 0.5 * (corners[0] + corners[1]);
  for (const auto& [a, b] : {std::pair{0.1, 0.9}, std::pair{0.9, 0.1}}) {
    // In the edge's normal cone, so nearest to the edge, but on the inner side of one face.
    const Vec3 away = (a * outward(0) + b * outward(1)).normalized();
    ASSERT_LT(std::min(away.dot(outward(0)), away.dot(outward(1))), 0.0);
    const Vec3 force = push_at(edge_middle, away);
    EXPECT_GT(force.dot(away), push_pN) << a;
  }
  for (const auto& [f, g] : {std::pair{0, 1}, std::pair{1, 2}, std::pair{0, 2}}) {
    // In corner 0's normal cone, on the inner side of its third face.
    const Vec3 away =
        (outward(static_cast<std::size_t>(f)) + outward(static_cast<std::size_t>(g))).normalized();
    const Vec3 force = push_at(corners[0], away);
    EXPECT_GT(force.dot(away), push_pN) << f << g;
  }
}

// Facing 12 x 12 patches `gap_um` apart, every vertex moved by up to `wobble_um` along each axis.
Patches wobbled_patches(double gap_um, double wobble_um, unsigned seed) {
  auto patches = facing_patches(gap_um, 12);
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> wobble(-wobble_um, wobble_um);
  for (Vec3& p : patches.positions_um)
    p += Vec3(wobble(generator), wobble(generator), wobble(generator));
  return patches;
}

// The plain reference of the law: each vertex against every triangle of the other patch, no cell
// list, no reach. Valid while no vertex is through the other patch (the push then points from the
// nearest point to the vertex).
std::vector<Vec3> brute_force_surface_forces(const Patches& p, const ContactParameters& law) {
  std::vector<Vec3> forces(p.positions_um.size(), Vec3::Zero());
  for (std::size_t i = 0; i < p.positions_um.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    std::size_t nearest_triangle = 0;
    std::array<double, 3> nearest_weights{};
    for (std::size_t t = 0; t < p.triangles.size(); ++t) {
      const auto& tri = p.triangles[t];
      if (p.owner[tri[0]] == p.owner[i]) continue;
      const auto w = nearest_on_triangle(p.positions_um[i], p.positions_um[tri[0]],
                                         p.positions_um[tri[1]], p.positions_um[tri[2]]);
      const Vec3 c = w[0] * p.positions_um[tri[0]] + w[1] * p.positions_um[tri[1]] +
                     w[2] * p.positions_um[tri[2]];
      const double d = (p.positions_um[i] - c).norm();
      if (d < nearest) nearest = d, nearest_triangle = t, nearest_weights = w;
    }
    if (!(nearest < law.range_um)) continue;
    const auto& tri = p.triangles[nearest_triangle];
    const Vec3 c = nearest_weights[0] * p.positions_um[tri[0]] +
                   nearest_weights[1] * p.positions_um[tri[1]] +
                   nearest_weights[2] * p.positions_um[tri[2]];
    const double excess = law.range_um / nearest - 1.0;
    const Vec3 push = law.force_at_contact_pN * excess * excess * (p.positions_um[i] - c) / nearest;
    forces[i] += push;
    for (std::size_t k = 0; k < 3; ++k) forces[tri[k]] -= nearest_weights[k] * push;
  }
  return forces;
}

TEST(SurfaceContact, EqualsThePlainSumOverEveryTriangle) {
  const auto patches = wobbled_patches(0.3, 0.08, 5);
  const auto push = push_of(patches, ContactLaw::surface);
  const auto expected = brute_force_surface_forces(patches, {5.0, 0.75, ContactLaw::surface});
  ASSERT_GT(push.statistics.pairs_in_range, 100u);
  for (std::size_t v = 0; v < expected.size(); ++v) {
    EXPECT_LT((push.forces_pN[v] - expected[v]).norm(), 1e-9 * (1.0 + expected[v].norm()))
        << "vertex " << v;
  }
}

TEST(SurfaceContact, ConservesMomentumAndIsThreadCountIndependent) {
  const auto patches = wobbled_patches(0.07, 0.03, 3);
  std::vector<std::vector<Vec3>> forces;
  for (const int threads : {1, 2}) {
    const ThreadCountScope scope(threads);
    const auto push = push_of(patches, ContactLaw::surface);
    EXPECT_GT(push.magnitude_pN, 0.0);
    EXPECT_LT(push.net_pN.norm(), 1e-12 * push.magnitude_pN);
    forces.push_back(push.forces_pN);
  }
  EXPECT_EQ(forces[0], forces[1]);
}

// The search shared as between two processes holding the same positions, each searching for one
// patch: here both "processes" in turn, the second handed the first's records ahead of its own
// (the order an all-gather may deliver). The forces are the unshared evaluation's, bit for bit.
TEST(SurfaceContact, ASearchSharedBetweenProcessesAddsUpAsOneProcess) {
  const auto patches = wobbled_patches(0.07, 0.03, 3);
  const ContactParameters parameters{5.0, 0.75, ContactLaw::surface};
  const auto evaluate = [&](const ContactSplit* split) {
    std::vector<Vec3> forces(patches.positions_um.size(), Vec3::Zero());
    ContactWorkspace workspace;
    const auto statistics =
        add_surface_contact_forces(patches.positions_um, patches.owner, patches.surfaces(),
                                   parameters, {}, forces, workspace, split);
    return std::make_pair(forces, statistics.pairs_in_range);
  };
  const auto [alone, pairs] = evaluate(nullptr);
  ASSERT_GT(pairs, 100u);
  std::vector<double> of_b;
  const ContactSplit searching_b{[](std::uint32_t cell) { return cell == 1; },
                                 [&of_b](std::span<const double> mine) {
                                   of_b.assign(mine.begin(), mine.end());
                                   return of_b;
                                 }};
  evaluate(&searching_b);
  ASSERT_FALSE(of_b.empty());
  const ContactSplit searching_a{[](std::uint32_t cell) { return cell == 0; },
                                 [&of_b](std::span<const double> mine) {
                                   std::vector<double> all = of_b;
                                   all.insert(all.end(), mine.begin(), mine.end());
                                   return all;
                                 }};
  const auto [shared, shared_pairs] = evaluate(&searching_a);
  EXPECT_EQ(shared_pairs, pairs);
  EXPECT_EQ(shared, alone);
}

}  // namespace
}  // namespace rbcsim::contact
