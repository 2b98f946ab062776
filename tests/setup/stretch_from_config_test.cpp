// stretch.* options -> cases::StretchSettings, and the forces text.
#include "setup/stretch_from_config.hpp"

#include <gtest/gtest.h>

#include "common/errors.hpp"

namespace {

using rbcsim::setup::stretch_forces_from;

std::string error_of(const std::string& text) {
  try {
    stretch_forces_from(text, "--forces");
  } catch (const rbcsim::InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(StretchFromConfig, DefaultsAreTheMillsForcesAndTheTwoMicrometreContact) {
  const auto settings = rbcsim::setup::stretch_settings_from(rbcsim::config::resolve_config());
  EXPECT_EQ(settings.mode, "quasi-static");
  ASSERT_EQ(settings.forces_pN.size(), 13u);
  EXPECT_EQ(settings.forces_pN.front(), 0.0);
  EXPECT_DOUBLE_EQ(settings.forces_pN.back(), 192.688);
  EXPECT_EQ(settings.contact.rule, "contact-diameter");
  EXPECT_EQ(settings.contact.diameter_um, 2.0);
  EXPECT_EQ(settings.relaxation, "fire");
  EXPECT_EQ(settings.relaxation_settings.force_tolerance_pN, 1e-4);
}

TEST(StretchFromConfig, OverridesReachTheSettings) {
  const auto config = rbcsim::config::resolve_config(
      {.assignments = {"stretch.forces_pN=0:200:50", "stretch.contact.rule=extreme-vertices",
                       "stretch.contact.extreme_vertex_count=12",
                       "stretch.quasi_static.relaxation=euler",
                       "stretch.quasi_static.max_iterations=77"}});
  const auto settings = rbcsim::setup::stretch_settings_from(config);
  EXPECT_EQ(settings.forces_pN, (std::vector<double>{0, 50, 100, 150, 200}));
  EXPECT_EQ(settings.contact.rule, "extreme-vertices");
  EXPECT_EQ(settings.contact.extreme_vertex_count, 12);
  EXPECT_EQ(settings.relaxation, "euler");
  EXPECT_EQ(settings.relaxation_settings.max_iterations, 77u);
}

TEST(StretchFromConfig, ForcesTextIsARangeOrTheReference) {
  EXPECT_EQ(stretch_forces_from("0:200", "x").size(), 9u);  // every 25 pN
  EXPECT_EQ(stretch_forces_from("10,5", "x"), (std::vector<double>{10, 5}));
  EXPECT_EQ(error_of("-5:10:5"), "--forces: forces must be >= 0 pN (the tweezers pull)");
  EXPECT_EQ(error_of("abc"), "--forces: range \"abc\": \"abc\" is not a number");
  EXPECT_THROW(rbcsim::config::resolve_config({.assignments = {"stretch.mode=fluid"}}),
               rbcsim::InputError);
}

}  // namespace
