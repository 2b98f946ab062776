// A force term added from outside the membrane module, as docs/architecture.md ("A membrane force
// term") tells a newcomer: one class and one registry row, here both in this file. The registry
// then lets MembraneModel run it by name beside a built-in term, the reference kernel evaluates
// it, the optimised kernel refuses it by naming membrane.kernel, and an unknown name is refused
// in the registry's one wording.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "membrane/force_terms.hpp"
#include "membrane/membrane_model.hpp"
#include "test_shapes.hpp"

namespace {

using rbcsim::Vec3;
using rbcsim::membrane::ForceDetail;
using rbcsim::membrane::ForceTerm;
using rbcsim::membrane::ForceTermEntry;
using rbcsim::membrane::MembraneModel;
using rbcsim::membrane::MembraneParameters;
using rbcsim::membrane::ReferenceState;
using rbcsim::membrane::TermContext;
using rbcsim::membrane::TermForces;
using rbcsim::membrane::TermScratch;

constexpr double kStiffness_pN_per_um = 2.5;

// E = k/2 sum_v |x_v - c|^2 about the centroid c: F_v = -k (x_v - c) (the c-derivative terms sum
// to zero because sum_v (x_v - c) = 0), so the net force is zero, as for any internal term.
class CentringTerm final : public ForceTerm {
 public:
  void evaluate(const TermContext& context, TermScratch&, TermForces& out) const override {
    const auto positions = context.positions_um;
    Vec3 centroid(0.0, 0.0, 0.0);
    for (const auto& x : positions) centroid += x;
    centroid /= static_cast<double>(positions.size());
    out.energy_pN_um = 0.0;
    for (std::size_t v = 0; v < positions.size(); ++v) {
      const Vec3 offset = positions[v] - centroid;
      out.forces_pN[v] = -kStiffness_pN_per_um * offset;
      out.energy_pN_um += 0.5 * kStiffness_pN_per_um * offset.squaredNorm();
    }
    out.max_abs_deviation = 0.0;
  }
};

std::unique_ptr<ForceTerm> make_centring_term(const MembraneParameters&, const ReferenceState&) {
  return std::make_unique<CentringTerm>();
}

// Registers the term for one test and removes it again, so that the other tests of this binary
// see the six built-in terms only.
class RegisteredTerm : public ::testing::Test {
 protected:
  void SetUp() override {
    rbcsim::membrane::force_term_registry().add(
        ForceTermEntry{"test_centring", make_centring_term});
  }
  void TearDown() override { rbcsim::membrane::force_term_registry().remove("test_centring"); }
};

MembraneParameters with_terms(std::vector<std::string> forces, std::string kernel) {
  MembraneParameters parameters;
  parameters.forces = std::move(forces);
  parameters.kernel = std::move(kernel);
  return parameters;
}

TEST_F(RegisteredTerm, RunsByNameBesideABuiltInTermInTheReferenceKernel) {
  const auto mesh = rbcsim::membrane_test::ellipsoid(2, Vec3(4.0, 3.0, 2.0));
  const MembraneModel model(mesh, with_terms({"link", "test_centring"}, "reference"));
  ASSERT_EQ(model.enabled_term_names().size(), 2u);
  EXPECT_EQ(model.enabled_term_names()[1], "test_centring");

  // Deformed: the link term then pulls too, and the total must be the sum of the two.
  auto positions = mesh.positions_um;
  for (auto& x : positions) x = Vec3(1.1 * x.x() + 0.3, x.y(), 0.9 * x.z());
  auto workspace = model.make_workspace();
  auto forces = model.make_forces();
  model.compute(positions, workspace, forces);

  Vec3 centroid(0.0, 0.0, 0.0);
  for (const auto& x : positions) centroid += x;
  centroid /= static_cast<double>(positions.size());
  const auto& centring = forces.term("test_centring");
  const auto& link = forces.term("link");
  Vec3 net(0.0, 0.0, 0.0);
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const Vec3 expected = -kStiffness_pN_per_um * (positions[v] - centroid);
    EXPECT_NEAR((centring.forces_pN[v] - expected).norm(), 0.0, 1e-12) << "vertex " << v;
    EXPECT_NEAR((forces.total_pN[v] - link.forces_pN[v] - expected).norm(), 0.0, 1e-9)
        << "vertex " << v;
    net += centring.forces_pN[v];
  }
  EXPECT_NEAR(net.norm(), 0.0, 1e-10);
  EXPECT_GT(centring.energy_pN_um, 0.0);
}

// The optimised kernel runs a term it has not fused as its own class beside the fused ones: the
// same per-term forces as the reference kernel's, bit for bit, and the same totals to round-off,
// with or without the per-term detail.
TEST_F(RegisteredTerm, RunsBesideTheFusedTermsInTheOptimisedKernel) {
  const auto mesh = rbcsim::membrane_test::ellipsoid(2, Vec3(4.0, 3.0, 2.0));
  auto positions = mesh.positions_um;
  for (auto& x : positions) x = Vec3(1.1 * x.x() + 0.3, x.y(), 0.9 * x.z());
  const auto compute = [&](const std::string& kernel, ForceDetail detail) {
    const MembraneModel model(mesh, with_terms({"link", "test_centring", "area"}, kernel));
    auto workspace = model.make_workspace();
    auto forces = model.make_forces();
    model.compute(positions, workspace, forces, detail);
    return forces;
  };
  const auto reference = compute("reference", ForceDetail::per_term);
  for (const auto detail : {ForceDetail::per_term, ForceDetail::totals}) {
    const auto optimised = compute("optimised", detail);
    double largest_pN = 0.0;
    for (const auto& f : reference.total_pN) largest_pN = std::max(largest_pN, f.norm());
    for (std::size_t v = 0; v < positions.size(); ++v) {
      EXPECT_NEAR((optimised.total_pN[v] - reference.total_pN[v]).norm(), 0.0, 1e-12 * largest_pN)
          << "vertex " << v;
    }
    if (detail == ForceDetail::per_term) {
      EXPECT_EQ(optimised.term("test_centring").forces_pN,
                reference.term("test_centring").forces_pN);
      EXPECT_EQ(optimised.term("test_centring").energy_pN_um,
                reference.term("test_centring").energy_pN_um);
      EXPECT_NEAR(optimised.term("area").energy_pN_um, reference.term("area").energy_pN_um,
                  1e-12 * reference.term("area").energy_pN_um);
    }
  }
}

TEST_F(RegisteredTerm, AnUnknownTermIsRefusedWithTheRegisteredNames) {
  const auto mesh = rbcsim::membrane_test::ellipsoid(1, Vec3(4.0, 3.0, 2.0));
  try {
    const MembraneModel model(mesh, with_terms({"link", "tension"}, "reference"));
    FAIL() << "an unknown term was accepted";
  } catch (const rbcsim::InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(
        message.find(
            "membrane.forces: \"tension\" is not one of link, bend, area, volume, area_difference, "
            "total_curvature, total_area, helfrich, local_area, viscosity, test_centring"),
        0u)
        << message;
  }
}

}  // namespace
