// rbcsim report as a user runs it: files written, --json on stdout, exit code 2 and one line for
// bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "report/run_fixtures.hpp"
#include "support/run_rbcsim.hpp"
#include "support/scratch_directory.hpp"

namespace {

using rbcsim::testing::read_text;
using rbcsim::testing::run_rbcsim;

// The path in single quotes for the shell. Built by appending: GCC 12 warns falsely
// (-Wrestrict) on "'" + std::string.
std::string quoted(const std::filesystem::path& path) {
  std::string text = path.string();
  text.insert(0, 1, '\'');
  return text.append(1, '\'');
}

TEST(ReportCommand, WritesTheReportAndSummaries) {
  rbcsim::testing::ScratchDirectory scratch;
  std::string arguments = "report";
  for (const auto& run : rbcsim::testing::write_standard_runs(scratch.path() / "runs")) {
    arguments.append(" ").append(quoted(run));
  }
  const auto output = scratch.path() / "out";
  const auto result = run_rbcsim(arguments + " -o " + quoted(output), scratch.path());
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");
  EXPECT_EQ(result.out, "wrote " + (output / "report.html").string() + "\nwrote " +
                            (output / "summary.md").string() + "\nwrote " +
                            (output / "summary.json").string() + "\n");
  EXPECT_NE(read_text(output / "report.html").find("<svg"), std::string::npos);
  EXPECT_NE(read_text(output / "summary.md").find("## Capillary transit"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(read_text(output / "summary.json")).at("run_count"), 13);

  const auto json =
      run_rbcsim(arguments + " --output " + quoted(output) + " --json", scratch.path());
  EXPECT_EQ(json.exit_code, 0) << json.err;
  EXPECT_EQ(json.out, read_text(output / "summary.json"));
}

TEST(ReportCommand, BadRunDirectoryIsOneLineAndExitCodeTwo) {
  rbcsim::testing::ScratchDirectory scratch;
  const auto good =
      rbcsim::testing::write_run(scratch.path() / "good", rbcsim::testing::calibrate_run());
  const auto missing = scratch.path() / "missing";
  const auto output = scratch.path() / "out";
  const auto result = run_rbcsim(
      "report " + quoted(good) + " " + quoted(missing) + " -o " + quoted(output), scratch.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "rbcsim: error: " + missing.string() + ": no such directory\n");
  EXPECT_FALSE(std::filesystem::exists(output));  // nothing written for a bad input
}

TEST(ReportCommand, OutputThatCannotBeADirectoryIsBadInput) {
  rbcsim::testing::ScratchDirectory scratch;
  const auto good =
      rbcsim::testing::write_run(scratch.path() / "good", rbcsim::testing::calibrate_run());
  const auto file = scratch.write("occupied", "a file, not a directory");
  const auto result =
      run_rbcsim("report " + quoted(good) + " -o " + quoted(file / "out"), scratch.path());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(
      result.err.rfind(
          "rbcsim: error: " + (file / "out").string() + ": cannot create the output directory", 0),
      0u)
      << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1);
}

TEST(ReportCommand, NoRunDirectoryIsAUsageError) {
  rbcsim::testing::ScratchDirectory scratch;
  EXPECT_EQ(run_rbcsim("report", scratch.path()).exit_code, 2);
}

}  // namespace
