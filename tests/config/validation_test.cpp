#include "config/validation.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "common/errors.hpp"

namespace {

using nlohmann::json;
using rbcsim::config::closest_known_path;
using rbcsim::config::closest_match;
using rbcsim::config::validate_tree;

// The diagnostic of validating `tree` from `source`, or "" when it is valid.
std::string problem_of(const json& tree, const std::string& source = "run.json") {
  try {
    validate_tree(tree, source);
  } catch (const rbcsim::InputError& error) {
    return error.what();
  }
  return "";
}

TEST(Validation, AcceptsPartialTreesAndAnnotations) {
  EXPECT_EQ(problem_of(json::object()), "");
  EXPECT_EQ(problem_of({{"membrane", {{"k_link_kBT", 9}}}}), "");
  EXPECT_EQ(problem_of({{"$schema", "../schemas/config.schema.json"},
                        {"derived", {{"dt_s", 1e-8}}},
                        {"lattice", {{"collision", "trt"}}}}),
            "");
}

TEST(Validation, UnknownKeySuggestsTheKnownOne) {
  EXPECT_EQ(problem_of({{"membrane", {{"k_bend_kbt", 3}}}}),
            "run.json: membrane.k_bend_kbt: unknown key; did you mean `membrane.k_bend_kBT`?");
  EXPECT_EQ(problem_of({{"k_bend_kBT", 3}}),
            "run.json: k_bend_kBT: unknown key; did you mean `membrane.k_bend_kBT`?");
  EXPECT_EQ(problem_of({{"membran", {{"k_link_kBT", 3}}}}),
            "run.json: membran: unknown key; did you mean `membrane`?");
  EXPECT_EQ(problem_of({{"zzzzzzzzzz", 1}}),
            "run.json: zzzzzzzzzz: unknown key (`rbcsim config schema` lists every key)");
}

TEST(Validation, WrongTypeNamesTheExpectedTypeAndUnit) {
  EXPECT_EQ(problem_of({{"membrane", {{"k_link_kBT", "seven"}}}}, "--set"),
            "--set: membrane.k_link_kBT: expected number (kBT), got string \"seven\"");
  EXPECT_EQ(problem_of({{"mesh", {{"subdivisions", 2.5}}}}),
            "run.json: mesh.subdivisions: expected integer, got number 2.5");
  EXPECT_EQ(problem_of({{"mesh", {{"file", 3}}}}),
            "run.json: mesh.file: expected string, got number 3");
  EXPECT_EQ(problem_of({{"membrane", 3}}),
            "run.json: membrane: expected an object (a group of options), got number 3");
  EXPECT_EQ(problem_of({{"$schema", 3}}), "run.json: $schema: expected string, got number 3");
  EXPECT_EQ(problem_of(json::array()),
            "run.json: expected a JSON object at the top level, got array");
}

TEST(Validation, OutOfRange) {
  EXPECT_EQ(problem_of({{"lattice", {{"relaxation_time", 0.5}}}}),
            "run.json: lattice.relaxation_time: must be > 0.5, got 0.5");
  EXPECT_EQ(problem_of({{"membrane", {{"k_bend_kBT", -1}}}}),
            "run.json: membrane.k_bend_kBT: must be >= 0, got -1");
  EXPECT_EQ(problem_of({{"mesh", {{"subdivisions", 7}}}}),
            "run.json: mesh.subdivisions: must be <= 6, got 7");
  EXPECT_EQ(problem_of({{"mesh", {{"subdivisions", 1}}}}), "");
  EXPECT_EQ(problem_of({{"membrane", {{"k_link_kBT", std::numeric_limits<double>::infinity()}}}}),
            "run.json: membrane.k_link_kBT: must be finite, got inf");
  EXPECT_EQ(problem_of({{"mesh", {{"subdivisions", 4000000000}}}}),
            "run.json: mesh.subdivisions: integer 4000000000 is out of range");
}

TEST(Validation, ChoicesAndLists) {
  EXPECT_EQ(problem_of({{"ibm", {{"kernel", "phi5"}}}}),
            "run.json: ibm.kernel: \"phi5\" is not one of phi2, phi3, phi4; did you mean `phi2`?");
  EXPECT_EQ(problem_of({{"membrane", {{"forces", json::array()}}}}), "");
  EXPECT_EQ(problem_of({{"membrane", {{"forces", {"link", "bnd"}}}}}),
            "run.json: membrane.forces: [1]: \"bnd\" is not one of link, bend, area, volume, "
            "area_difference, total_curvature, total_area, helfrich, local_area, viscosity; did "
            "you mean `bend`?");
  EXPECT_EQ(problem_of({{"membrane", {{"forces", {"link", "link"}}}}}),
            "run.json: membrane.forces: lists \"link\" more than once");
  EXPECT_EQ(problem_of({{"membrane", {{"forces", "link"}}}}),
            "run.json: membrane.forces: expected array of strings, each one of link, bend, area, "
            "volume, area_difference, total_curvature, total_area, helfrich, local_area, "
            "viscosity, got string "
            "\"link\"");
}

// suspension.cells: each element an object of known keys, the morphology one of the choices, the
// vectors three finite numbers, the axis not zero; the diagnostic names the element and key.
TEST(Validation, CellLists) {
  const auto cells = [](const json& list) { return json{{"suspension", {{"cells", list}}}}; };
  EXPECT_EQ(problem_of(cells(json::array())), "");
  EXPECT_EQ(problem_of(cells({{{"morphology", "discocyte"}, {"centre_um", {1, 0, 0}}},
                              {{"morphology", "stomatocyte-II"},
                               {"centre_um", {9.5, 1, -1}},
                               {"axis", {1, 0, 0}},
                               {"spin_deg", 30}}})),
            "");
  EXPECT_EQ(problem_of(cells({{{"morphology", "discocyte"}}})),
            "run.json: suspension.cells: [0]: missing centre_um");
  EXPECT_EQ(problem_of(cells({{{"morphology", "discocite"}, {"centre_um", {0, 0, 0}}}})),
            "run.json: suspension.cells: [0].morphology: \"discocite\" is not one of "
            "stomatocyte-II, discocyte, echinocyte-III; did you mean `discocyte`?");
  EXPECT_EQ(problem_of(cells({{{"morphology", "discocyte"}, {"centre_um", {0, 0}}}})),
            "run.json: suspension.cells: [0].centre_um: expected 3 finite numbers, got an array "
            "of 2");
  EXPECT_EQ(problem_of(cells(
                {{{"morphology", "discocyte"}, {"centre_um", {0, 0, 0}}, {"axis", {0, 0, 0}}}})),
            "run.json: suspension.cells: [0].axis: the zero vector has no direction");
  EXPECT_EQ(
      problem_of(cells({{{"morphology", "discocyte"}, {"centre_um", {0, 0, 0}}, {"angle", 3}}})),
      "run.json: suspension.cells: [0].angle: unknown key (a cell has morphology, "
      "mesh_file, centre_um, axis, spin_deg)");
  EXPECT_EQ(problem_of(cells({{{"morphology", "discocyte"},
                               {"mesh_file", "cells/bent.stl"},
                               {"centre_um", {0, 0, 0}}}})),
            "");
  EXPECT_EQ(problem_of(cells(
                {{{"morphology", "discocyte"}, {"mesh_file", ""}, {"centre_um", {0, 0, 0}}}})),
            "run.json: suspension.cells: [0].mesh_file: an empty path");
  EXPECT_EQ(problem_of(
                cells({{{"morphology", "discocyte"}, {"mesh_file", 3}, {"centre_um", {0, 0, 0}}}})),
            "run.json: suspension.cells: [0].mesh_file: expected string, got number 3");
  EXPECT_EQ(problem_of(cells({"discocyte"})),
            "run.json: suspension.cells: [0]: expected an object, got string \"discocyte\"");
}

TEST(Validation, DottedKeysMustBeNested) {
  EXPECT_EQ(problem_of({{"membrane.k_link_kBT", 3}}),
            "run.json: membrane.k_link_kBT: keys are single names; nest objects instead of dots");
}

TEST(Validation, ClosestMatch) {
  const std::vector<std::string> words{"discocyte", "stomatocyte-II", "echinocyte-III"};
  EXPECT_EQ(closest_match("stomatocyte-ii", words), "stomatocyte-II");
  EXPECT_EQ(closest_match("echinocyte", words), "echinocyte-III");
  EXPECT_EQ(closest_match("sphere", words), std::nullopt);
  EXPECT_EQ(closest_known_path("lattice.spacing"), "lattice.spacing_um");
}

}  // namespace
