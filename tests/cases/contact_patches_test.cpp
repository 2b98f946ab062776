// Contact patches on the Evans-Fung discocytes: where the tweezers hold the cell, and the forces.
#include "cases/contact_patches.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cases/stretch_case.hpp"
#include "common/errors.hpp"
#include "stretch_test_support.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::cases::ContactSettings;
using rbcsim::cases::prepare_stretch_cell;
using rbcsim::cases::select_contact_patches;
namespace support = rbcsim::cases::testing;

class EvansFungDiscocyte : public ::testing::TestWithParam<int> {};

// The 2 um contact: every patch vertex lies within 1 um of its end, the two ends are the cell's
// extremes along x, and the patch holds roughly the vertices of a 2 um disc (pi um^2 of a
// membrane of ~134 um^2), the same number at both ends.
TEST_P(EvansFungDiscocyte, ContactDiameterPatchesAreSymmetricDiscsAtTheEnds) {
  const auto cell = prepare_stretch_cell(support::evans_fung_discocyte(GetParam()), {});
  const auto& positions = cell.mesh.positions_um;
  const auto [low, high] =
      std::minmax_element(positions.begin(), positions.end(),
                          [](const Vec3& a, const Vec3& b) { return a.x() < b.x(); });
  const auto& patches = cell.patches;
  ASSERT_FALSE(patches.positive_end.empty());
  EXPECT_EQ(patches.positive_end.size(), patches.negative_end.size());
  for (const auto vertex : patches.positive_end) EXPECT_LE((positions[vertex] - *high).norm(), 1.0);
  for (const auto vertex : patches.negative_end) EXPECT_LE((positions[vertex] - *low).norm(), 1.0);
  // No vertex outside a patch is within 1 um of its end (the rule takes all of them).
  std::size_t near_positive_end = 0;
  for (const auto& p : positions) near_positive_end += (p - *high).norm() <= 1.0 ? 1 : 0;
  EXPECT_EQ(near_positive_end, patches.positive_end.size());
  // Vertex density x disc area, within a factor 2 (the rim is curved, the density not uniform).
  const double expected = static_cast<double>(positions.size()) / 134.0 * M_PI;
  EXPECT_GT(static_cast<double>(patches.positive_end.size()), expected / 2);
  EXPECT_LT(static_cast<double>(patches.positive_end.size()), expected * 2);
  // The icosphere-based discocyte is symmetric under p -> -p: each patch is the other's image.
  for (const auto vertex : patches.positive_end) {
    const Vec3 image = -positions[vertex];
    EXPECT_TRUE(
        std::any_of(patches.negative_end.begin(), patches.negative_end.end(),
                    [&](std::int32_t other) { return (positions[other] - image).norm() < 1e-6; }))
        << "vertex " << vertex;
  }
}

TEST_P(EvansFungDiscocyte, ExtremeVerticesRuleTakesTheNLargestAndSmallestX) {
  const auto mesh = prepare_stretch_cell(support::evans_fung_discocyte(GetParam()), {}).mesh;
  const ContactSettings settings{.rule = "extreme-vertices", .extreme_vertex_count = 7};
  const auto patches = select_contact_patches(mesh.positions_um, settings);
  ASSERT_EQ(patches.positive_end.size(), 7u);
  ASSERT_EQ(patches.negative_end.size(), 7u);
  auto xs = std::vector<double>();
  for (const auto& p : mesh.positions_um) xs.push_back(p.x());
  std::sort(xs.begin(), xs.end());
  for (const auto vertex : patches.positive_end) {
    EXPECT_GE(mesh.positions_um[vertex].x(), xs[xs.size() - 7]);
  }
  for (const auto vertex : patches.negative_end) EXPECT_LE(mesh.positions_um[vertex].x(), xs[6]);
}

INSTANTIATE_TEST_SUITE_P(Levels, EvansFungDiscocyte, ::testing::Values(3, 4));

TEST(ContactPatches, TweezerForcesSplitTheTotalEquallyAndCancel) {
  const auto cell = prepare_stretch_cell(support::evans_fung_discocyte(3), {});
  const auto forces = rbcsim::cases::tweezer_forces_pN(cell.mesh.vertex_count(), cell.patches, 40);
  Vec3 positive_sum = Vec3::Zero();
  Vec3 negative_sum = Vec3::Zero();
  for (const auto vertex : cell.patches.positive_end) positive_sum += forces[vertex];
  for (const auto vertex : cell.patches.negative_end) negative_sum += forces[vertex];
  EXPECT_NEAR((positive_sum - Vec3(40, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((negative_sum - Vec3(-40, 0, 0)).norm(), 0.0, 1e-12);
  const double share = 40.0 / static_cast<double>(cell.patches.positive_end.size());
  EXPECT_DOUBLE_EQ(forces[cell.patches.positive_end.front()].x(), share);
  std::size_t loaded = 0;
  for (const auto& force : forces) loaded += force.norm() > 0 ? 1 : 0;
  EXPECT_EQ(loaded, cell.patches.positive_end.size() + cell.patches.negative_end.size());
}

TEST(ContactPatches, PatchesThatWouldOverlapOrAnUnknownRuleAreInputErrors) {
  const auto mesh = support::evans_fung_discocyte(3);
  const auto message = [&mesh](const ContactSettings& settings) {
    try {
      prepare_stretch_cell(mesh, settings);
    } catch (const rbcsim::InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({.diameter_um = 20.0}),
            "stretch.contact.diameter_um: the two contact patches overlap: too large for this "
            "cell");
  EXPECT_EQ(message({.rule = "extreme-vertices", .extreme_vertex_count = 400}),
            "stretch.contact.extreme_vertex_count: the two contact patches overlap: too large for "
            "this cell");
  EXPECT_EQ(message({.rule = "glue"}),
            "stretch.contact.rule: \"glue\" is not one of contact-diameter, extreme-vertices");
}

}  // namespace
