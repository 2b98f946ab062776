// rbcsim config show | schema: the fully resolved configuration (with the derived lattice
// values) and the JSON Schema of config files, both generated from the one option table.
#include <iostream>
#include <memory>

#include "command_registry.hpp"
#include "common_options.hpp"
#include "config/config.hpp"
#include "config/reference_page.hpp"
#include "config/schema.hpp"

namespace rbcsim::cli::config_command {
namespace {

void attach_config_command(CLI::App& application) {
  auto* command = application.add_subcommand(
      "config", "Show the resolved configuration, its schema or its reference page");
  command->require_subcommand(1);

  auto* show = command->add_subcommand(
      "show", "Print the fully resolved configuration as JSON, with the derived lattice values");
  auto request = std::make_shared<config::ConfigRequest>();
  add_config_options(show, *request);
  show->callback([request] {
    const auto resolved = config::config_with_derived_values(config::resolve_config(*request));
    std::cout << resolved.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
  });

  auto* schema = command->add_subcommand(
      "schema", "Print the JSON Schema of config files (shipped as schemas/config.schema.json)");
  schema->callback([] { std::cout << config::config_schema_text(); });

  auto* reference = command->add_subcommand(
      "reference",
      "Print the Markdown reference of every option (shipped as docs/configuration.md)");
  reference->callback([] { std::cout << config::configuration_reference_markdown(); });
}

const bool registered = register_command({"config", 90, attach_config_command});

}  // namespace
}  // namespace rbcsim::cli::config_command
