#include "config/option_table.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>

#include "config/validation.hpp"

namespace {

using nlohmann::json;
using rbcsim::config::option_table;
using rbcsim::config::OptionTable;
using rbcsim::config::OptionType;

json default_of(const std::string& path) {
  const auto* option = option_table().find(path);
  if (!option) {
    ADD_FAILURE() << "no option " << path;
    return nullptr;
  }
  return option->default_value;
}

// The names other modules rely on, with the defaults of the task brief and the paper's Table 2
// (discocyte), typed here from those documents rather than from the table.
TEST(OptionTable, HoldsTheAgreedNamesAndDefaults) {
  EXPECT_EQ(default_of("morphology"), "discocyte");
  EXPECT_EQ(default_of("physics.plasma_density_kg_per_m3"), 1025.0);
  EXPECT_EQ(default_of("physics.plasma_kinematic_viscosity_m2_per_s"), 1.1e-6);
  EXPECT_EQ(default_of("physics.thermal_energy_J"), 4.100531391e-21);
  EXPECT_EQ(default_of("lattice.spacing_um"), 0.5);
  EXPECT_EQ(default_of("lattice.relaxation_time"), 1.0);
  EXPECT_EQ(default_of("lattice.collision"), "trt");
  EXPECT_EQ(default_of("lattice.trt_magic"), 0.1875);
  EXPECT_EQ(default_of("ibm.kernel"), "phi2");
  EXPECT_EQ(default_of("membrane.k_link_kBT"), 7.0);
  EXPECT_EQ(default_of("membrane.k_bend_kBT"), 50.0);
  EXPECT_EQ(default_of("membrane.k_area_kBT"), 5.0);
  EXPECT_EQ(default_of("membrane.k_volume_kBT"), 20.0);
  EXPECT_EQ(default_of("membrane.k_area_difference_kBT"), 300.0);
  EXPECT_EQ(default_of("membrane.k_total_curvature_kBT"), 100.0);
  EXPECT_EQ(default_of("membrane.tau_link"), 3.0);
  EXPECT_EQ(default_of("membrane.tau_bend_rad"), 0.5235987755982988);
  EXPECT_DOUBLE_EQ(default_of("membrane.tau_bend_rad").get<double>(), std::numbers::pi / 6);
  EXPECT_EQ(default_of("membrane.tau_area"), 0.3);
  EXPECT_EQ(default_of("membrane.tau_volume"), 0.1);
  EXPECT_EQ(default_of("membrane.tau_area_difference"), 1.5);
  EXPECT_EQ(default_of("membrane.tau_total_curvature"), 3.87);
  EXPECT_EQ(default_of("membrane.persistence_length_um"), 0.0075);
  EXPECT_EQ(default_of("membrane.force_length_scale_um"), 0.25);
  EXPECT_EQ(default_of("membrane.forces"),
            json({"link", "bend", "area", "volume", "area_difference", "total_curvature"}));
  EXPECT_EQ(default_of("membrane.distribution"), "gradient");
  EXPECT_EQ(default_of("membrane.vertex_force_cap_pN"), 50.0);
  EXPECT_EQ(default_of("mesh.file"), "");
  EXPECT_EQ(default_of("mesh.subdivisions"), 4);
}

TEST(OptionTable, ChoicesAndRangesOfTheVariants) {
  const auto& table = option_table();
  // The shapes of the sequence that have a Table 2 parameter set, in sequence order.
  EXPECT_EQ(table.find("morphology")->choices,
            (std::vector<std::string>{"stomatocyte-II", "discocyte", "echinocyte-III"}));
  EXPECT_EQ(table.find("ibm.kernel")->choices, (std::vector<std::string>{"phi2", "phi3", "phi4"}));
  EXPECT_EQ(table.find("lattice.collision")->choices, (std::vector<std::string>{"bgk", "trt"}));
  EXPECT_EQ(table.find("membrane.distribution")->choices,
            (std::vector<std::string>{"paper", "gradient", "vertex"}));
  const auto& subdivisions = *table.find("mesh.subdivisions");
  EXPECT_EQ(subdivisions.type, OptionType::integer);
  EXPECT_TRUE(subdivisions.minimum && subdivisions.minimum->value == 1 &&
              subdivisions.minimum->inclusive);
  EXPECT_TRUE(subdivisions.maximum && subdivisions.maximum->value == 6 &&
              subdivisions.maximum->inclusive);
  const auto& tau = *table.find("lattice.relaxation_time");
  EXPECT_TRUE(tau.minimum && tau.minimum->value == 0.5 && !tau.minimum->inclusive);
}

TEST(OptionTable, EveryRowIsDocumentedAndItsDefaultValid) {
  for (const auto& option : option_table().options()) {
    EXPECT_FALSE(option.doc.empty()) << option.path;
    EXPECT_EQ(rbcsim::config::value_problem(option, option.default_value), std::nullopt)
        << option.path;
  }
}

TEST(OptionTable, StiffnessesAreInKBTAndLengthsInMicrometres) {
  for (const auto& option : option_table().options()) {
    if (option.path.ends_with("_kBT")) {
      EXPECT_EQ(option.unit, "kBT") << option.path;
    }
    // A unit ending in a length is the unit with its factors spelt out (membrane.viscosity_Pa_s_um:
    // Pa s um, the 2D viscosity); a plain _um key is a length.
    if (option.path.ends_with("_Pa_s_um")) {
      EXPECT_EQ(option.unit, "Pa s um") << option.path;
    } else if (option.path.ends_with("_um")) {
      EXPECT_EQ(option.unit, "um") << option.path;
    }
  }
}

TEST(OptionTable, RejectsDuplicateAndCollidingPaths) {
  OptionTable table;
  table.add_number("group.value_um", "um", 1.0, "A length.");
  EXPECT_THROW(table.add_number("group.value_um", "um", 2.0, "Again."), std::logic_error);
  EXPECT_THROW(table.add_boolean("group", true, "A group cannot be an option."), std::logic_error);
  EXPECT_THROW(table.add_boolean("group.value_um.sub", true, "Nor an option a group."),
               std::logic_error);
}

TEST(OptionTable, GroupsAndDefaultsTree) {
  const auto& table = option_table();
  EXPECT_TRUE(table.is_group("membrane"));
  EXPECT_FALSE(table.is_group("membrane.k_link_kBT"));
  EXPECT_FALSE(table.is_group("membran"));
  const auto defaults = table.defaults();
  EXPECT_EQ(defaults["membrane"]["k_link_kBT"], 7.0);
  EXPECT_EQ(defaults["mesh"]["subdivisions"], 4);
  const auto known = table.known_paths();
  EXPECT_NE(std::find(known.begin(), known.end(), "membrane"), known.end());
  EXPECT_NE(std::find(known.begin(), known.end(), "membrane.k_link_kBT"), known.end());
}

}  // namespace
