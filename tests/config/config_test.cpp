#include "config/config.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "config/config_sources.hpp"
#include "support/scratch_directory.hpp"

namespace {

using nlohmann::json;
using rbcsim::InputError;
using rbcsim::config::ConfigRequest;
using rbcsim::config::resolve_config;
using rbcsim::testing::ScratchDirectory;

struct Table2Stiffnesses {
  const char* morphology;
  double link, bend, area, volume, area_difference, total_curvature;
};

// Table 2 of the paper (k in kBT), typed from the paper.
constexpr Table2Stiffnesses kTable2[] = {
    {"discocyte", 7, 50, 5, 20, 300, 100},
    {"echinocyte-III", 11, 70, 5, 20, 420, 140},
    {"stomatocyte-II", 11, 80, 5, 20, 660, 220},
};

TEST(ResolveConfig, NoArgumentsGiveTheDiscocyteDefaults) {
  const auto config = resolve_config();
  EXPECT_EQ(config.string("morphology"), "discocyte");
  EXPECT_EQ(config.number("membrane.k_link_kBT"), 7.0);
  EXPECT_EQ(config.number("lattice.relaxation_time"), 1.0);
  EXPECT_EQ(config.integer("mesh.subdivisions"), 4);
  EXPECT_EQ(config.string("mesh.file"), "");
  EXPECT_EQ(config.string_list("membrane.forces").size(), 6u);
}

TEST(ResolveConfig, EachMorphologyGetsItsTable2Stiffnesses) {
  for (const auto& row : kTable2) {
    const auto config = resolve_config({.morphology = row.morphology});
    EXPECT_EQ(config.string("morphology"), row.morphology);
    EXPECT_EQ(config.number("membrane.k_link_kBT"), row.link) << row.morphology;
    EXPECT_EQ(config.number("membrane.k_bend_kBT"), row.bend) << row.morphology;
    EXPECT_EQ(config.number("membrane.k_area_kBT"), row.area) << row.morphology;
    EXPECT_EQ(config.number("membrane.k_volume_kBT"), row.volume) << row.morphology;
    EXPECT_EQ(config.number("membrane.k_area_difference_kBT"), row.area_difference)
        << row.morphology;
    EXPECT_EQ(config.number("membrane.k_total_curvature_kBT"), row.total_curvature)
        << row.morphology;
    // The limits of Table 2 are shared by the three morphologies.
    EXPECT_EQ(config.number("membrane.tau_area_difference"), 1.5) << row.morphology;
  }
}

TEST(ResolveConfig, LaterSourcesOverrideEarlierOnes) {
  const ScratchDirectory directory;
  const auto first = directory.write(
      "first.json",
      R"({"membrane": {"k_link_kBT": 8, "k_bend_kBT": 60}, "lattice": {"spacing_um": 0.4}})");
  const auto second = directory.write("second.json", R"({"membrane": {"k_bend_kBT": 61}})");
  const auto config =
      resolve_config({.files = {first, second},
                      .assignments = {"lattice.spacing_um=0.25", "lattice.spacing_um=0.3"}});
  EXPECT_EQ(config.number("membrane.k_link_kBT"), 8.0);   // first file over the defaults
  EXPECT_EQ(config.number("membrane.k_bend_kBT"), 61.0);  // second file over the first
  EXPECT_EQ(config.number("lattice.spacing_um"), 0.3);    // last --set over everything
  EXPECT_EQ(config.number("membrane.k_area_difference_kBT"), 300.0);  // untouched: the overlay's
}

TEST(ResolveConfig, FilesOverrideTheMorphologyOverlay) {
  const ScratchDirectory directory;
  const auto file = directory.write("stiff.json", R"({"membrane": {"k_bend_kBT": 90}})");
  const auto config = resolve_config({.morphology = "stomatocyte-II", .files = {file}});
  EXPECT_EQ(config.number("membrane.k_bend_kBT"), 90.0);
  EXPECT_EQ(config.number("membrane.k_area_difference_kBT"), 660.0);
}

TEST(ResolveConfig, MorphologyComesFromTheLastSourceThatSetsIt) {
  const ScratchDirectory directory;
  const auto echinocyte = directory.write("e.json", R"({"morphology": "echinocyte-III"})");
  const auto neutral = directory.write("n.json", R"({"lattice": {"collision": "trt"}})");
  EXPECT_EQ(resolve_config({.files = {echinocyte, neutral}}).number("membrane.k_bend_kBT"), 70.0);
  const auto from_set =
      resolve_config({.files = {echinocyte}, .assignments = {"morphology=stomatocyte-II"}});
  EXPECT_EQ(from_set.string("morphology"), "stomatocyte-II");
  EXPECT_EQ(from_set.number("membrane.k_bend_kBT"), 80.0);
  const auto from_option = resolve_config({.morphology = "discocyte",
                                           .files = {echinocyte},
                                           .assignments = {"morphology=stomatocyte-II"}});
  EXPECT_EQ(from_option.string("morphology"), "discocyte");
  EXPECT_EQ(from_option.number("membrane.k_bend_kBT"), 50.0);
}

// The presets (share/config/presets): `paper` is the paper's membrane as printed, the default;
// `physiological` bends as the bilayer does (Helfrich's energy in place of Eq. 7), adds the
// bilayer's area incompressibility (whole and per triangle), membrane viscosity and the
// cytoplasm's viscosity at their literature values, and holds each cell's enclosed volume. Every
// other layer (morphology, files, --set) goes over a preset.
TEST(ResolveConfig, PresetsAreWholeParameterSetsUnderEveryOtherLayer) {
  const auto paper = resolve_config();
  EXPECT_EQ(paper.string("preset"), "paper");
  const std::vector<std::string> six = {"link", "bend", "area", "volume", "area_difference",
                                        "total_curvature"};
  EXPECT_EQ(paper.string_list("membrane.forces"), six);
  EXPECT_FALSE(paper.boolean("ibm.hold_volume"));  // HemoCell has no such step
  const auto physiological = resolve_config({.morphology = "echinocyte-III",
                                             .preset = "physiological"});
  EXPECT_EQ(physiological.string("preset"), "physiological");
  const std::vector<std::string> with_both = {"link",       "helfrich",        "area",
                                              "volume",     "area_difference", "total_curvature",
                                              "total_area", "local_area",      "viscosity"};
  EXPECT_EQ(physiological.string_list("membrane.forces"), with_both);
  EXPECT_EQ(physiological.number("membrane.viscosity_Pa_s_um"), 0.5);  // Hochmuth & Hampel 1979
  EXPECT_EQ(physiological.number("physics.cytoplasm_viscosity_ratio"), 5.0);
  EXPECT_TRUE(physiological.boolean("ibm.hold_volume"));  // the membrane lets no water through
  EXPECT_EQ(paper.number("physics.cytoplasm_viscosity_ratio"), 1.0);
  EXPECT_EQ(physiological.number("membrane.k_bend_kBT"), 70.0);       // the morphology's still
  const ScratchDirectory directory;
  const auto file = directory.write("p.json", R"({"preset": "physiological"})");
  const auto chosen_in_a_file =
      resolve_config({.files = {file}, .assignments = {"membrane.viscosity_Pa_s_um=0.1"}});
  EXPECT_EQ(chosen_in_a_file.string("preset"), "physiological");
  EXPECT_EQ(chosen_in_a_file.string_list("membrane.forces"), with_both);
  EXPECT_EQ(chosen_in_a_file.number("membrane.viscosity_Pa_s_um"), 0.1);  // --set over it
  try {
    resolve_config({.preset = "healthy"});
    FAIL() << "accepted an unknown preset";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "--preset: \"healthy\" is not one of paper, physiological");
  }
}

TEST(ResolveConfig, BadInputNamesItsSource) {
  const ScratchDirectory directory;
  const auto typo = directory.write("typo.json", R"({"membrane": {"k_bend_kbt": 3}})");
  try {
    resolve_config({.files = {typo}});
    FAIL() << "accepted an unknown key";
  } catch (const InputError& error) {
    EXPECT_EQ(
        std::string(error.what()),
        typo.string() + ": membrane.k_bend_kbt: unknown key; did you mean `membrane.k_bend_kBT`?");
  }
  EXPECT_THROW(resolve_config({.morphology = "spherocyte"}), InputError);
  EXPECT_THROW(resolve_config({.files = {directory.path() / "missing.json"}}), InputError);
  EXPECT_THROW(resolve_config({.files = {directory.path()}}), InputError);
}

TEST(Config, TypedReadsRejectWrongTypesAndUnknownPaths) {
  const auto config = resolve_config();
  EXPECT_EQ(config.number("mesh.subdivisions"), 4.0);  // an integer reads as a number too
  EXPECT_THROW(config.integer("lattice.spacing_um"), std::logic_error);
  EXPECT_THROW(config.string("lattice.spacing_um"), std::logic_error);
  EXPECT_THROW(config.number("lattice.spacing"), std::logic_error);
  EXPECT_THROW(config.string_list("morphology"), std::logic_error);
  EXPECT_EQ(config.json()["ibm"]["kernel"], "phi2");
}

TEST(Config, UnitConverterOfTheConfiguration) {
  const auto config = resolve_config({.assignments = {"lattice.spacing_um=0.25"}});
  const auto converter = rbcsim::config::make_unit_converter(config);
  // dt = (1 - 1/2)/3 * (2.5e-7 m)^2 / 1.1e-6 m^2/s
  EXPECT_DOUBLE_EQ(converter.dt_s(), (0.5 / 3.0) * 6.25e-14 / 1.1e-6);
  EXPECT_THROW(rbcsim::config::make_unit_converter(
                   resolve_config({.assignments = {"lattice.relaxation_time=0.5001"}})),
               InputError);
}

TEST(Config, ShownConfigurationReadsBackAsTheSameConfiguration) {
  const ScratchDirectory directory;
  const auto original =
      resolve_config({.morphology = "echinocyte-III", .assignments = {"ibm.kernel=phi4"}});
  const auto shown = rbcsim::config::config_with_derived_values(original);
  EXPECT_DOUBLE_EQ(shown["derived"]["dt_s"].get<double>(), (0.5 / 3.0) * 2.5e-13 / 1.1e-6);
  const auto file = directory.write("shown.json", shown.dump(2));
  EXPECT_EQ(resolve_config({.files = {file}}).json(), original.json());
}

}  // namespace
