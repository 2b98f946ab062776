// The options every subcommand shares (DESIGN.md §1): --config, --set, --morphology, --output,
// --threads, --json, --quiet, --verbose. A subcommand declares a CommonOptions that outlives the
// parse (e.g. in a shared_ptr captured by its callback), calls add_common_options, and in its
// callback calls resolve_config.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>

#include "config/config.hpp"

namespace rbcsim::cli {

struct CommonOptions {
  config::ConfigRequest config;  // --config (repeatable), --set (repeatable), --morphology
  std::filesystem::path output_directory;  // --output; empty: the subcommand's default
  int threads = 0;                         // --threads; 0: OpenMP's default (all cores)
  bool json = false;                       // --json: machine-readable result on stdout
  bool quiet = false;                      // --quiet
  bool verbose = false;                    // --verbose (excludes --quiet)
};

// Only the options that build the configuration, for commands that run nothing (config show).
void add_config_options(CLI::App* command, config::ConfigRequest& request);

void add_common_options(CLI::App* command, CommonOptions& options);

// config::resolve_config of the options given; throws InputError (exit 2) on bad input.
config::Config resolve_config(const CommonOptions& options);

}  // namespace rbcsim::cli
