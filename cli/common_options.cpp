#include "common_options.hpp"

#include <string>

#include "config/option_table.hpp"

namespace rbcsim::cli {
namespace {

std::string morphology_help() {
  const auto& option = *config::option_table().find("morphology");
  std::string help = "Cell morphology and its Table 2 parameters:";
  for (const auto& choice : option.choices) help.append(" ").append(choice);
  return help + " (default: " + option.default_value.get<std::string>() +
         "; overrides config files and --set)";
}

}  // namespace

void add_config_options(CLI::App* command, config::ConfigRequest& request) {
  command
      ->add_option("--config", request.files,
                   "JSON config file; repeatable, later files override earlier ones")
      ->type_name("FILE")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command
      ->add_option("--set", request.assignments,
                   "Override one option, e.g. --set membrane.k_bend_kBT=60; repeatable, applied "
                   "after the config files")
      ->type_name("KEY.PATH=VALUE")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command->add_option("--morphology", request.morphology, morphology_help())->type_name("NAME");
}

void add_common_options(CLI::App* command, CommonOptions& options) {
  add_config_options(command, options.config);
  command->add_option("--output", options.output_directory, "Directory for the run's files")
      ->type_name("DIR");
  command->add_option("--threads", options.threads, "OpenMP threads (default: all cores)")
      ->type_name("N")
      ->check(CLI::PositiveNumber);
  command->add_flag("--json", options.json, "Print the machine-readable result on stdout");
  auto* quiet = command->add_flag("--quiet", options.quiet, "Print only errors");
  command->add_flag("--verbose", options.verbose, "Print more detail")->excludes(quiet);
}

config::Config resolve_config(const CommonOptions& options) {
  return config::resolve_config(options.config);
}

}  // namespace rbcsim::cli
