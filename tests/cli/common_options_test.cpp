// The options every subcommand shares, parsed as CLI11 parses a real command line.
#include "common_options.hpp"

#include <gtest/gtest.h>

namespace {

using rbcsim::cli::add_common_options;
using rbcsim::cli::CommonOptions;

// A subcommand "run" with the common options and one positional MESH, as `capillary [MESH]` has.
struct ParsedCommand {
  CommonOptions options;
  std::string mesh;

  explicit ParsedCommand(const std::string& command_line) {
    CLI::App application{"test"};
    auto* run = application.add_subcommand("run");
    add_common_options(run, options);
    run->add_option("mesh", mesh);
    application.parse(command_line, false);
  }
};

TEST(CommonOptions, DefaultsWhenNothingIsGiven) {
  const ParsedCommand parsed("run");
  EXPECT_EQ(parsed.options.config.morphology, std::nullopt);
  EXPECT_TRUE(parsed.options.config.files.empty());
  EXPECT_TRUE(parsed.options.config.assignments.empty());
  EXPECT_TRUE(parsed.options.output_directory.empty());
  EXPECT_EQ(parsed.options.threads, 0);
  EXPECT_FALSE(parsed.options.json || parsed.options.quiet || parsed.options.verbose);
}

TEST(CommonOptions, RepeatableOptionsKeepTheirOrderAndLeavePositionalsAlone) {
  const ParsedCommand parsed(
      "run --config a.json cell.stl --set membrane.k_link_kBT=8 --config b.json "
      "--set=lattice.spacing_um=0.25 --morphology echinocyte-III --output out --threads 2 --json "
      "--verbose");
  const auto& request = parsed.options.config;
  ASSERT_EQ(request.files.size(), 2u);
  EXPECT_EQ(request.files[0], "a.json");
  EXPECT_EQ(request.files[1], "b.json");
  EXPECT_EQ(request.assignments,
            (std::vector<std::string>{"membrane.k_link_kBT=8", "lattice.spacing_um=0.25"}));
  EXPECT_EQ(request.morphology, "echinocyte-III");
  EXPECT_EQ(parsed.mesh, "cell.stl");
  EXPECT_EQ(parsed.options.output_directory, "out");
  EXPECT_EQ(parsed.options.threads, 2);
  EXPECT_TRUE(parsed.options.json);
  EXPECT_TRUE(parsed.options.verbose);
}

TEST(CommonOptions, UsageErrors) {
  EXPECT_THROW(ParsedCommand("run --quiet --verbose"), CLI::ParseError);
  EXPECT_THROW(ParsedCommand("run --threads 0"), CLI::ParseError);
  EXPECT_THROW(ParsedCommand("run --threads many"), CLI::ParseError);
  EXPECT_THROW(ParsedCommand("run --set"), CLI::ParseError);
}

// A refused count reads like every other rbcsim complaint (option: "value" problem), not as
// CLI11's "Value 0 not in range 0.000000 to 1.79769e+308".
TEST(CommonOptions, AThreadCountBelowOneIsRefusedInRbcsimsWording) {
  for (const std::string value : {"0", "-2", "many", "2.5"}) {
    try {
      ParsedCommand("run --threads " + value);
      FAIL() << "--threads " << value << " was accepted";
    } catch (const CLI::ParseError& error) {
      EXPECT_EQ(std::string(error.what()),
                "--threads: \"" + value + "\" is not a whole number >= 1");
    }
  }
}

TEST(CommonOptions, ResolvesTheConfiguration) {
  const ParsedCommand parsed("run --morphology stomatocyte-II --set membrane.k_link_kBT=12");
  const auto config = rbcsim::cli::resolve_config(parsed.options);
  EXPECT_EQ(config.number("membrane.k_bend_kBT"), 80.0);  // Table 2, stomatocyte II
  EXPECT_EQ(config.number("membrane.k_link_kBT"), 12.0);
}

}  // namespace
