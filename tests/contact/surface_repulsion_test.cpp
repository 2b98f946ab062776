// The surface contact law (contact/surface_repulsion.hpp): the nearest point of a triangle, and
// two facing membrane patches whose vertices are offset sideways, the arrangement in which two
// cells of a 10 um tube run passed through each other under the vertex-pair law. Vertex pairs lose
// their normal push as the gap closes; the surface law's grows, pushes a vertex that is already
// through back out, conserves momentum and does not depend on the thread count.
#include "contact/surface_repulsion.hpp"

#include <gtest/gtest.h>

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
  std::vector<std::vector<std::uint32_t>> of_vertex(p.positions_um.size());
  for (std::uint32_t t = 0; t < p.triangles.size(); ++t) {
    for (const auto v : p.triangles[t]) of_vertex[v].push_back(t);
  }
  p.offsets.push_back(0);
  for (const auto& row : of_vertex) {
    p.vertex_triangles.insert(p.vertex_triangles.end(), row.begin(), row.end());
    p.offsets.push_back(static_cast<std::uint32_t>(p.vertex_triangles.size()));
  }
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

TEST(SurfaceContact, ConservesMomentumAndIsThreadCountIndependent) {
  auto patches = facing_patches(0.07, 12);
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> wobble(-0.03, 0.03);
  for (Vec3& p : patches.positions_um)
    p += Vec3(wobble(generator), wobble(generator), wobble(generator));
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

}  // namespace
}  // namespace rbcsim::contact
