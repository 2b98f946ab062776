// The options every subcommand shares (docs/commands/README.md): --config, --set, --morphology,
// --preset, --output, --threads, --json, --quiet, --verbose. A subcommand declares a
// CommonOptions that outlives the parse (e.g. in a shared_ptr captured by its callback), calls
// add_common_options, and in its callback calls resolve_config.
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "config/config.hpp"

namespace rbcsim::cli {

struct CommonOptions {
  config::ConfigRequest config;            // --config, --set (repeatable), --morphology, --preset
  std::filesystem::path output_directory;  // --output; empty: the subcommand's default
  int threads = 0;                         // --threads; 0: OpenMP's default (all cores)
  bool json = false;                       // --json: machine-readable result on stdout
  bool quiet = false;                      // --quiet
  bool verbose = false;                    // --verbose (excludes --quiet)
  bool resuming = false;                   // --resume given: output_directory holds a run
};

// --checkpoint-every and --resume, for the commands whose runs are long (the coupled ones):
// add_checkpoint_options, then run_directory.hpp's wire_checkpoints once the simulation is built.
struct CheckpointOptions {
  std::string every;                       // --checkpoint-every; empty: only when interrupted
  std::filesystem::path resume_directory;  // --resume; also the run's output directory
};

// How often: a whole number of steps, or wall-clock time with a unit (s, m, h).
struct CheckpointInterval {
  std::size_t steps = 0;
  double wall_s = 0.0;
};

// "5000" -> 5000 steps; "90s", "10m", "2h" -> wall-clock seconds. InputError naming
// --checkpoint-every otherwise.
CheckpointInterval parse_checkpoint_interval(std::string_view text);

// Adds both options; --resume DIR makes DIR the output directory (and excludes --output) and sets
// CommonOptions::resuming.
void add_checkpoint_options(CLI::App* command, CheckpointOptions& options, CommonOptions& common);

// `help` followed by " (default: X)", X the option table's default of config key `path`: a help
// text never states a default of its own (logic_error for a path that is not an option).
std::string with_default(std::string help, std::string_view path);

// `text` as a whole number (all of it: "2x" and "2.5" are not), or nullopt.
std::optional<long long> whole_number(const std::string& text);

// A check for an option that takes a whole number >= minimum; its complaint reads like rbcsim's
// others (`--threads: "0" is not a whole number >= 1`), not CLI11's range text.
CLI::Validator whole_number_at_least(long long minimum);

// Only the options that build the configuration, for commands that run nothing (config show).
void add_config_options(CLI::App* command, config::ConfigRequest& request);

void add_common_options(CLI::App* command, CommonOptions& options);

// For a command option that stands for a config key (--geometry for capillary.geometry): adds
// "path=value" to the request after the --set assignments, so config.json records it and a bad
// value is diagnosed under the option's own name, not as --set.
void assign_option(config::ConfigRequest& request, std::string_view option, std::string_view path,
                   const std::string& value);

// config::resolve_config of the options given; throws InputError (exit 2) on bad input.
config::Config resolve_config(const CommonOptions& options);

// Notices (import repairs, run notices) on stderr, one "rbcsim: notice: " line each.
void print_notices(std::span<const std::string> notices);

}  // namespace rbcsim::cli
