// The cell list against a brute-force search, and the contact force's law, antisymmetry and
// thread-count independence (core/contact).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "common/thread_count_scope.hpp"
#include "contact/cell_list.hpp"
#include "contact/cell_repulsion.hpp"

namespace rbcsim::contact {
namespace {

std::vector<Vec3> random_points(std::size_t count, const Vec3& extent_um, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> points;
  for (std::size_t p = 0; p < count; ++p) {
    points.push_back(random_vec3(unit, generator).cwiseProduct(extent_um));
  }
  return points;
}

using PairSet = std::set<std::pair<std::size_t, std::size_t>>;

PairSet pairs_within(const std::vector<Vec3>& points, double reach, const PeriodicBox& box,
                     const CellList* list) {
  PairSet pairs;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto consider = [&](std::size_t j) {
      if (j != i && box.minimum_image(points[i] - points[j]).norm() < reach) pairs.insert({i, j});
    };
    if (list) {
      list->for_each_candidate(points[i], [&](std::uint32_t j) { consider(j); });
    } else {
      for (std::size_t j = 0; j < points.size(); ++j) consider(j);
    }
  }
  return pairs;
}

// Every pair within the reach is a candidate, with and without periodic axes (one of them only
// two bins long, where the -1 and +1 neighbour bins coincide), and none is visited twice.
TEST(CellList, FindsEveryPairTheBruteForceSearchFinds) {
  const auto points = random_points(600, Vec3(7.0, 5.0, 3.1), 11);
  for (const PeriodicBox box :
       {PeriodicBox{}, PeriodicBox{{7.0, 0.0, 0.0}}, PeriodicBox{{7.0, 5.0, 3.1}}}) {
    CellList list;
    list.build(points, 1.5, box);
    const auto expected = pairs_within(points, 1.5, box, nullptr);
    EXPECT_GT(expected.size(), 1000u);
    EXPECT_EQ(pairs_within(points, 1.5, box, &list), expected);
    for (const Vec3& point : points) {
      std::multiset<std::uint32_t> seen;
      list.for_each_candidate(point, [&](std::uint32_t j) { seen.insert(j); });
      for (const auto j : seen) ASSERT_EQ(seen.count(j), 1u);
    }
  }
}

// A period shorter than the reach would need more than one image of a point.
TEST(CellList, RefusesAPeriodShorterThanTheReach) {
  CellList list;
  const std::vector<Vec3> points{Vec3::Zero()};
  EXPECT_THROW(list.build(points, 2.0, PeriodicBox{{1.5, 0.0, 0.0}}), std::invalid_argument);
  EXPECT_THROW(list.build(points, 0.0, PeriodicBox{}), std::invalid_argument);
}

// Two vertices of different cells at d = range / 2: F = F0 (1/2)^2 along the separation, the
// partner's exactly opposite; at the range and beyond, nothing; vertices of one cell, nothing.
TEST(CellContact, FollowsItsLawBetweenCellsOnly) {
  const ContactParameters parameters{8.0, 0.5};
  ContactWorkspace workspace;
  const std::vector<Vec3> positions{Vec3(0.0, 0.0, 0.0), Vec3(0.15, 0.2, 0.0)};  // d = 0.25
  std::vector<Vec3> forces(2, Vec3::Zero());
  const std::vector<std::uint32_t> owners{0, 1};
  const auto statistics =
      add_cell_contact_forces(positions, owners, parameters, {}, forces, workspace);
  EXPECT_NEAR(forces[0].norm(), 8.0 * 0.25, 1e-12);
  EXPECT_NEAR(forces[0].dot(Vec3(-0.6, -0.8, 0.0)), 2.0, 1e-12);
  EXPECT_EQ(forces[1], Vec3(-forces[0]));
  EXPECT_EQ(statistics.pairs_in_range, 2u);
  EXPECT_EQ(statistics.close_pairs, 0u);
  EXPECT_NEAR(statistics.closest_um, 0.25, 1e-15);

  std::vector<Vec3> same_cell(2, Vec3::Zero());
  const std::vector<std::uint32_t> one_owner{3, 3};
  add_cell_contact_forces(positions, one_owner, parameters, {}, same_cell, workspace);
  EXPECT_EQ(same_cell[0], Vec3::Zero());

  // The vertices must come cell by cell.
  const std::vector<Vec3> three(3, Vec3::Zero());
  std::vector<Vec3> three_forces(3, Vec3::Zero());
  const std::vector<std::uint32_t> interleaved{0, 1, 0};
  EXPECT_THROW(add_cell_contact_forces(three, interleaved, parameters, {}, three_forces, workspace),
               std::invalid_argument);

  const std::vector<Vec3> apart{Vec3::Zero(), Vec3(0.5, 0.0, 0.0)};
  std::vector<Vec3> none(2, Vec3::Zero());
  add_cell_contact_forces(apart, owners, parameters, {}, none, workspace);
  EXPECT_EQ(none[0], Vec3::Zero());
}

// Across a periodic seam the nearest image pushes: vertices at x = 0.1 and 9.9 in a period of 10
// are 0.2 apart, and the first is pushed towards +x.
TEST(CellContact, ActsAcrossAPeriodicSeam) {
  ContactWorkspace workspace;
  const std::vector<Vec3> positions{Vec3(0.1, 0.0, 0.0), Vec3(9.9, 0.0, 0.0)};
  std::vector<Vec3> forces(2, Vec3::Zero());
  const std::vector<std::uint32_t> owners{0, 1};
  add_cell_contact_forces(positions, owners, {1.0, 0.4}, PeriodicBox{{10.0, 0.0, 0.0}}, forces,
                          workspace);
  EXPECT_NEAR(forces[0].x(), 0.25, 1e-12);
  EXPECT_EQ(forces[1], Vec3(-forces[0]));
}

// Many vertices of five cells crowded together: the net force vanishes to round-off (each pair
// force is antisymmetric bit for bit), and 1 and 2 threads give identical forces.
TEST(CellContact, NetForceVanishesAndThreadsDoNotMatter) {
  auto positions = random_points(2000, Vec3(6.0, 6.0, 6.0), 5);
  std::vector<std::uint32_t> owners;
  for (std::size_t p = 0; p < positions.size(); ++p)
    owners.push_back(static_cast<std::uint32_t>(5 * p / positions.size()));
  const ContactParameters parameters{10.0, 0.6};
  const PeriodicBox box{{6.0, 0.0, 0.0}};
  // Some cells a few periods away: positions are never wrapped, the contact wraps them.
  for (std::size_t p = 0; p < positions.size(); p += 7) positions[p].x() += 18.0;
  std::vector<std::vector<Vec3>> by_threads;
  for (const int threads : {1, 2}) {
    const ThreadCountScope scope(threads);
    ContactWorkspace workspace;
    std::vector<Vec3> forces(positions.size(), Vec3::Zero());
    add_cell_contact_forces(positions, owners, parameters, box, forces, workspace);
    by_threads.push_back(forces);
  }
  EXPECT_EQ(by_threads[0], by_threads[1]);
  Vec3 net = Vec3::Zero();
  double magnitude = 0.0;
  for (const Vec3& force : by_threads[0]) {
    net += force;
    magnitude += force.norm();
  }
  EXPECT_GT(magnitude, 1000.0);
  EXPECT_LT(net.norm(), 1e-12 * magnitude);
}

// The plain reference: every pair of different cells, O(points^2), minimum images.
std::vector<Vec3> brute_force_contact(const std::vector<Vec3>& positions,
                                      const std::vector<std::uint32_t>& owners,
                                      const ContactParameters& parameters, const PeriodicBox& box,
                                      std::size_t& pairs) {
  std::vector<Vec3> forces(positions.size(), Vec3::Zero());
  pairs = 0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    for (std::size_t j = 0; j < positions.size(); ++j) {
      if (owners[i] == owners[j]) continue;
      const Vec3 separation = box.minimum_image(positions[i] - positions[j]);
      const double distance = separation.norm();
      if (distance >= parameters.range_um) continue;
      ++pairs;
      const double closeness = 1.0 - distance / parameters.range_um;
      forces[i] += (parameters.force_at_contact_pN * closeness * closeness / distance) * separation;
    }
  }
  return forces;
}

// Forty "cells" (balls of 60 points, 1.2 um across) scattered in a box periodic along x, some
// touching, one across the seam, some whole periods away: the broad phase (cell boxes) keeps
// every vertex with a partner, so the forces and pair count are the brute-force search's (the
// order of summation differs, hence 1e-12).
TEST(CellContact, EqualsTheBruteForceSumOverEveryPair) {
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const PeriodicBox box{{12.0, 0.0, 0.0}};
  std::vector<Vec3> positions;
  std::vector<std::uint32_t> owners;
  for (std::uint32_t cell = 0; cell < 40; ++cell) {
    Vec3 centre = random_vec3(unit, generator).cwiseProduct(Vec3(12.0, 6.0, 6.0));
    if (cell == 0) centre.x() = 11.9;       // across the seam
    if (cell % 9 == 4) centre.x() += 24.0;  // two periods on
    for (int p = 0; p < 60; ++p) {
      positions.push_back(centre + 0.6 * (random_vec3(unit, generator) - Vec3(0.5, 0.5, 0.5)));
      owners.push_back(cell);
    }
  }
  const ContactParameters parameters{5.0, 0.5};
  std::size_t expected_pairs = 0;
  const auto expected = brute_force_contact(positions, owners, parameters, box, expected_pairs);
  ContactWorkspace workspace;
  std::vector<Vec3> forces(positions.size(), Vec3::Zero());
  const auto statistics =
      add_cell_contact_forces(positions, owners, parameters, box, forces, workspace);
  EXPECT_GT(expected_pairs, 100u);
  EXPECT_EQ(statistics.pairs_in_range, expected_pairs);
  // Some cells are apart from all others: the broad phase must have dropped their vertices.
  EXPECT_LT(workspace.candidates.size(), positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    EXPECT_LT((forces[i] - expected[i]).norm(), 1e-12 * (1.0 + expected[i].norm())) << i;
  }
}

}  // namespace
}  // namespace rbcsim::contact
