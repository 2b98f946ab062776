#include "geometry/wall_registry.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "common/errors.hpp"
#include "test_meshes.hpp"

namespace {

using namespace rbcsim::geometry;
using nlohmann::json;

std::string wall_shape_error(const std::string& name, const json& parameters,
                             const MeshLoader& load_mesh = {}) {
  try {
    make_wall_shape(name, parameters, "capillary.wall", load_mesh);
  } catch (const rbcsim::InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(WallRegistry, EveryShapeHasAUniqueNameAndASummary) {
  std::set<std::string_view> names;
  for (const auto& kind : wall_shape_kinds()) {
    EXPECT_TRUE(names.insert(kind.name).second) << kind.name;
    EXPECT_FALSE(kind.summary.empty()) << kind.name;
  }
  for (const auto* name :
       {"channel", "tube", "capillary", "paper-validation", "paper-morphology", "stl"}) {
    EXPECT_TRUE(names.contains(name)) << name;
  }
}

TEST(WallRegistry, BuildsShapesFromJson) {
  const auto tube = make_wall_shape("tube", {{"diameter_um", 8.0}, {"length_um", 20.0}});
  EXPECT_DOUBLE_EQ(*tube->radius_at_um(3.0), 4.0);

  const auto channel =
      make_wall_shape("channel", {{"gap_um", 10.0}, {"length_um", 8.0}, {"width_um", 6.0}});
  EXPECT_TRUE(channel->is_fluid({0.0, 4.9, 0.0}));
  EXPECT_FALSE(channel->is_fluid({0.0, -5.1, 0.0}));
  EXPECT_FALSE(channel->radius_at_um(0.0).has_value());

  const auto capillary = make_wall_shape("capillary", {{"length_um", 30.0},
                                                       {"inlet_diameter_um", 10.0},
                                                       {"throat_diameter_um", 6.0},
                                                       {"profile", "linear"},
                                                       {"constriction_length_um", 12.0}});
  EXPECT_DOUBLE_EQ(*capillary->radius_at_um(30.0), 5.0);    // outlet defaults to the inlet
  EXPECT_NEAR(*capillary->radius_at_um(12.0), 4.0, 1e-12);  // linear, halfway in
}

TEST(WallRegistry, PresetsWithAndWithoutOverrides) {
  const auto validation = make_wall_shape("paper-validation");
  EXPECT_DOUBLE_EQ(*validation->radius_at_um(0.0), 5.1);
  EXPECT_DOUBLE_EQ(*validation->radius_at_um(15.6), 3.375);

  const auto morphology = make_wall_shape("paper-morphology", json::object());
  EXPECT_DOUBLE_EQ(*morphology->radius_at_um(21.0), 3.4);

  const auto narrower = make_wall_shape(
      "paper-morphology", {{"throat_diameter_um", 5.0}, {"constriction_length_um", 20.0}});
  EXPECT_DOUBLE_EQ(*narrower->radius_at_um(21.0), 2.5);
  EXPECT_DOUBLE_EQ(*narrower->radius_at_um(11.0), 5.0);  // start of [11, 31]
  EXPECT_LT(*narrower->radius_at_um(11.5), 5.0);
}

TEST(WallRegistry, ErrorsNameTheJsonPath) {
  EXPECT_EQ(wall_shape_error("paper-validation", {{"throat_diamter_um", 6.0}}),
            "capillary.wall.throat_diamter_um: unknown parameter of this wall shape");
  EXPECT_EQ(wall_shape_error("capillary", {{"length_um", 30.0}, {"inlet_diameter_um", 10.0}}),
            "capillary.wall.throat_diameter_um: missing (a number is required)");
  EXPECT_EQ(wall_shape_error("tube", {{"diameter_um", "wide"}, {"length_um", 3.0}}),
            "capillary.wall.diameter_um: expected a number, got string");
  EXPECT_EQ(wall_shape_error("paper-validation", json::array()),
            "capillary.wall: expected an object of shape parameters, got array");
  EXPECT_NE(wall_shape_error("paper-validation", {{"throat_diameter_um", 10.2}})
                .find("capillary.wall.throat_diameter_um: must be smaller than inlet_diameter_um"),
            std::string::npos);
  EXPECT_NE(wall_shape_error("tube", {{"diameter_um", 4.0}, {"length_um", -1.0}})
                .find("capillary.wall.length_um: must be a positive length"),
            std::string::npos);
  EXPECT_NE(wall_shape_error("paper-validation", {{"profile", "step"}})
                .find("capillary.wall.profile: \"step\" is not one of cosine, linear"),
            std::string::npos);
  EXPECT_NE(
      wall_shape_error("pipe", json::object()).find("capillary.wall: \"pipe\" is not one of"),
      std::string::npos);
}

TEST(WallRegistry, StlShapeReadsItsSurfaceThroughTheLoader) {
  std::string asked_for;
  const MeshLoader load_box = [&asked_for](const std::string& path) {
    asked_for = path;
    return test_meshes::box_mesh(rbcsim::Vec3::Zero(), rbcsim::Vec3(10.0, 2.0, 2.0));
  };
  const auto wall =
      make_wall_shape("stl", {{"file", "block.stl"}, {"open_axes", {"x"}}}, "geometry", load_box);
  EXPECT_EQ(asked_for, "block.stl");
  EXPECT_TRUE(wall->is_fluid({5.0, 1.0, 1.0}));
  const auto bounds = wall->fluid_bounds();
  EXPECT_TRUE(bounds.open_axes[0]);
  EXPECT_FALSE(bounds.open_axes[1] || bounds.open_axes[2]);

  EXPECT_EQ(wall_shape_error("stl", {{"file", "block.stl"}, {"open_axes", {"w"}}}, load_box),
            "capillary.wall.open_axes: unknown axis \"w\" (x, y or z)");
  EXPECT_EQ(wall_shape_error("stl", {{"file", "block.stl"}}),
            "capillary.wall.file: this command cannot read wall surface files");
  EXPECT_EQ(wall_shape_error("stl", json::object(), load_box),
            "capillary.wall.file: missing (a string is required)");
}

}  // namespace
