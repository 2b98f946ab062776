#include "config/config_sources.hpp"

#include <gtest/gtest.h>

#include "common/errors.hpp"

namespace {

using nlohmann::json;
using rbcsim::InputError;
using rbcsim::config::parse_assignment;
using rbcsim::config::parse_config_text;
using rbcsim::config::parse_json;

template <typename Function>
std::string input_error_of(Function&& function) {
  try {
    function();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(ParseJson, SyntaxErrorsGiveLineAndColumn) {
  // Positions counted by hand: the offending character is the `x` on line 3 (column 8), the `}`
  // after a trailing comma on line 4 (column 3), and the missing `]` at the end of line 1.
  EXPECT_EQ(input_error_of([] {
              parse_json("{\n  \"a\": 1,\n  \"b\": x\n}", "a.json");
            }).rfind("a.json: line 3, column 8: syntax error", 0),
            0u);
  EXPECT_EQ(input_error_of([] {
              parse_json("{\n  \"m\": {\n    \"k\": 3,\n  }\n}\n", "b.json");
            }).rfind("b.json: line 4, column 3: syntax error while parsing object key", 0),
            0u);
  EXPECT_EQ(input_error_of([] {
              parse_json("{\"a\": [1,2", "c.json");
            }).rfind("c.json: line 1, column 11: ", 0),
            0u);
  EXPECT_EQ(input_error_of([] {
              parse_json("", "empty.json");
            }).rfind("empty.json: line 1, column 1: ", 0),
            0u);
}

TEST(ParseJson, ErrorMessageIsOneLineWithoutTheParserPrefix) {
  const auto message = input_error_of([] { parse_json("{\"a\": }", "d.json"); });
  EXPECT_EQ(message.find('\n'), std::string::npos);
  EXPECT_EQ(message.find("json.exception"), std::string::npos) << message;
}

TEST(ParseJson, NumberOverflowIsBadInput) {
  EXPECT_EQ(input_error_of([] { parse_json("{\"a\": 1e999}", "e.json"); }),
            "e.json: number overflow parsing '1e999'");
}

TEST(ParseConfigText, ValidatesAfterParsing) {
  EXPECT_EQ(
      parse_config_text("{\"lattice\": {\"spacing_um\": 0.25}}", "x.json")["lattice"]["spacing_um"],
      0.25);
  EXPECT_EQ(
      input_error_of([] { parse_config_text("{\"lattice\": {\"spacing\": 0.25}}", "x.json"); }),
      "x.json: lattice.spacing: unknown key; did you mean `lattice.spacing_um`?");
}

TEST(ParseAssignment, ValuesParseAsJsonElseAsStrings) {
  EXPECT_EQ(parse_assignment("lattice.spacing_um=0.25"),
            json({{"lattice", {{"spacing_um", 0.25}}}}));
  EXPECT_EQ(parse_assignment("membrane.distribution=paper"),
            json({{"membrane", {{"distribution", "paper"}}}}));
  EXPECT_EQ(parse_assignment("membrane.forces=[\"link\",\"bend\"]"),
            json({{"membrane", {{"forces", {"link", "bend"}}}}}));
  EXPECT_EQ(parse_assignment("membrane={\"k_link_kBT\": 9}"),
            json({{"membrane", {{"k_link_kBT", 9}}}}));
}

TEST(ParseAssignment, ListsAlsoReadCommasAndStringsKeepTheirText) {
  EXPECT_EQ(parse_assignment("membrane.forces=link,bend"),
            json({{"membrane", {{"forces", {"link", "bend"}}}}}));
  EXPECT_EQ(parse_assignment("mesh.file=42"), json({{"mesh", {{"file", "42"}}}}));
  EXPECT_EQ(parse_assignment("mesh.file=\"cell.stl\""), json({{"mesh", {{"file", "cell.stl"}}}}));
  EXPECT_EQ(parse_assignment("mesh.file=a=b.stl"), json({{"mesh", {{"file", "a=b.stl"}}}}));
}

TEST(ParseAssignment, Diagnostics) {
  EXPECT_EQ(input_error_of([] { parse_assignment("membrane.k_link_kBT"); }),
            "--set: expected key.path=value, got \"membrane.k_link_kBT\"");
  EXPECT_EQ(input_error_of([] { parse_assignment("=3"); }),
            "--set: expected key.path=value, got \"=3\"");
  EXPECT_EQ(input_error_of([] { parse_assignment("membrane.k_link_kBT=seven"); }),
            "--set: membrane.k_link_kBT: expected number (kBT), got string \"seven\"");
  EXPECT_EQ(input_error_of([] { parse_assignment("membrane..k_link_kBT=3"); }),
            "--set: membrane..k_link_kBT: empty key in the path");
  EXPECT_EQ(input_error_of([] { parse_assignment("derived.dt_s=1"); }),
            "--set: derived.dt_s: written by rbcsim, cannot be set");
}

}  // namespace
