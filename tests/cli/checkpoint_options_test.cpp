// --checkpoint-every and --resume, parsed as CLI11 parses a real command line.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common_options.hpp"

namespace {

using rbcsim::cli::parse_checkpoint_interval;

TEST(CheckpointOptions, StepsOrWallClockTime) {
  EXPECT_EQ(parse_checkpoint_interval("5000").steps, 5000u);
  EXPECT_EQ(parse_checkpoint_interval("5000").wall_s, 0.0);
  EXPECT_EQ(parse_checkpoint_interval("90s").wall_s, 90.0);
  EXPECT_EQ(parse_checkpoint_interval("10m").wall_s, 600.0);
  EXPECT_EQ(parse_checkpoint_interval("1.5h").wall_s, 5400.0);
  EXPECT_EQ(parse_checkpoint_interval("1.5h").steps, 0u);
  for (const char* bad : {"", "0", "1.5", "10 m", "10d", "m", "-5", "1.2.3s", "0s"}) {
    EXPECT_THROW(parse_checkpoint_interval(bad), rbcsim::InputError) << bad;
  }
}

TEST(CheckpointOptions, ResumeIsTheOutputDirectoryAndExcludesOutput) {
  rbcsim::cli::CommonOptions common;
  rbcsim::cli::CheckpointOptions checkpoint;
  CLI::App application{"test"};
  auto* run = application.add_subcommand("run");
  add_common_options(run, common);
  add_checkpoint_options(run, checkpoint, common);
  application.parse("run --resume runs/a --checkpoint-every 10m", false);
  EXPECT_EQ(checkpoint.resume_directory, "runs/a");
  EXPECT_EQ(common.output_directory, "runs/a");
  EXPECT_EQ(checkpoint.every, "10m");
  EXPECT_THROW(application.parse("run --resume runs/a --output runs/b", false), CLI::ParseError);
  EXPECT_THROW(application.parse("run --checkpoint-every 10x", false), CLI::ParseError);
}

}  // namespace
