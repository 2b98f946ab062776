// rbcsim config show | schema, run as a user runs them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"

namespace {

using nlohmann::json;
using rbcsim::testing::run_rbcsim;
using rbcsim::testing::ScratchDirectory;

TEST(ConfigCommand, ShowWithNoArgumentsPrintsTheDefaultsAndDerivedValues) {
  const ScratchDirectory scratch;
  const auto result = run_rbcsim("config show", scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");
  const auto shown = json::parse(result.out);
  EXPECT_EQ(shown["morphology"], "discocyte");
  EXPECT_EQ(shown["membrane"]["k_bend_kBT"], 50);
  // dt = (1 - 1/2)/3 * (0.5 um)^2 / 1.1e-6 m^2/s = 3.7879e-8 s
  EXPECT_NEAR(shown["derived"]["dt_s"].get<double>(), 3.7879e-8, 0.00005e-8);
  EXPECT_DOUBLE_EQ(shown["derived"]["lattice_kinematic_viscosity"].get<double>(), 1.0 / 6.0);
}

TEST(ConfigCommand, MorphologySelectsTable2) {
  const ScratchDirectory scratch;
  const auto result = run_rbcsim("config show --morphology stomatocyte-II", scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto shown = json::parse(result.out);
  EXPECT_EQ(shown["morphology"], "stomatocyte-II");
  EXPECT_EQ(shown["membrane"]["k_bend_kBT"], 80);
  EXPECT_EQ(shown["membrane"]["k_area_difference_kBT"], 660);
}

TEST(ConfigCommand, OverrideOrderFilesThenSets) {
  const ScratchDirectory scratch;
  scratch.write("a.json",
                R"({"membrane": {"k_link_kBT": 8, "k_bend_kBT": 60}, "ibm": {"kernel": "phi3"}})");
  scratch.write("b.json", R"({"membrane": {"k_bend_kBT": 65}})");
  const auto result = run_rbcsim("config show --config '" + (scratch.path() / "a.json").string() +
                                     "' --set membrane.k_link_kBT=9 --config '" +
                                     (scratch.path() / "b.json").string() +
                                     "' --set membrane.distribution=paper"
                                     " --set 'membrane.forces=[\"link\",\"bend\"]'",
                                 scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto shown = json::parse(result.out);
  EXPECT_EQ(shown["membrane"]["k_link_kBT"], 9);   // --set after every file
  EXPECT_EQ(shown["membrane"]["k_bend_kBT"], 65);  // b.json after a.json
  EXPECT_EQ(shown["ibm"]["kernel"], "phi3");
  EXPECT_EQ(shown["membrane"]["distribution"], "paper");
  EXPECT_EQ(shown["membrane"]["forces"], json({"link", "bend"}));
}

TEST(ConfigCommand, UnknownKeyExitsWithTwoAndSuggestsTheKey) {
  const ScratchDirectory scratch;
  const auto file = scratch.write("typo.json", "{\n  \"membrane\": {\"k_bend_kbt\": 3}\n}\n");
  const auto result = run_rbcsim("config show --config '" + file.string() + "'", scratch.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.out, "");
  EXPECT_EQ(result.err,
            "rbcsim: error: " + file.string() +
                ": membrane.k_bend_kbt: unknown key; did you mean `membrane.k_bend_kBT`?\n");
}

TEST(ConfigCommand, SyntaxErrorGivesLineAndColumn) {
  const ScratchDirectory scratch;
  const auto file =
      scratch.write("broken.json", "{\n  \"lattice\": {\n    \"spacing_um\": 0.5,\n  }\n}\n");
  const auto result = run_rbcsim("config show --config '" + file.string() + "'", scratch.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find(file.string() + ": line 4, column 3: syntax error"), std::string::npos)
      << result.err;
}

TEST(ConfigCommand, BadValuesExitWithTwo) {
  const ScratchDirectory scratch;
  for (const char* arguments :
       {"config show --set lattice.relaxation_time=0.4",
        "config show --set lattice.relaxation_time=0.5001", "config show --morphology spherocyte",
        "config show --set membrane.k_link_kBT=stiff", "config show --config", "config"}) {
    const auto result = run_rbcsim(arguments, scratch.path());
    EXPECT_EQ(result.exit_code, 2) << arguments;
    EXPECT_NE(result.err, "") << arguments;
  }
}

TEST(ConfigCommand, ShownConfigurationIsAValidConfigFile) {
  const ScratchDirectory scratch;
  const auto first =
      run_rbcsim("config show --morphology echinocyte-III --set ibm.kernel=phi4", scratch.path());
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const auto file = scratch.write("shown.json", first.out);
  const auto again = run_rbcsim("config show --config '" + file.string() + "'", scratch.path());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(json::parse(again.out), json::parse(first.out));
}

TEST(ConfigCommand, SchemaPrintsTheShippedSchema) {
  const ScratchDirectory scratch;
  const auto result = run_rbcsim("config schema", scratch.path());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.out == rbcsim::testing::read_text(std::string(RBCSIM_SOURCE_DIR) +
                                                       "/schemas/config.schema.json"))
      << "refresh with: rbcsim config schema > schemas/config.schema.json";
}

}  // namespace
