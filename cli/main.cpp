// rbcsim: entry point. Maps failures onto exit codes (README.md, "Exit codes"):
// 0 success, 1 runtime failure (instability, NaN), 2 bad input (usage, config, mesh), 130
// interrupted by SIGINT or SIGTERM (the results so far written).
#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "command_registry.hpp"
#include "common/errors.hpp"
#include "common/interrupt.hpp"

int main(int argc, char** argv) {
  CLI::App application{
      "rbcsim — red blood cells (discocyte, stomatocyte II, echinocyte III) stretched, sheared\n"
      "and squeezed through capillaries: D3Q19 lattice Boltzmann plasma, six-force membrane,\n"
      "immersed-boundary coupling.",
      "rbcsim"};
  application.set_version_flag("--version", std::string("rbcsim ") + RBCSIM_VERSION);
  application.require_subcommand(1);
  for (const auto& command : rbcsim::cli::registered_commands()) command.attach(application);

  rbcsim::install_interrupt_handlers();
  try {
    application.parse(argc, argv);
  } catch (const CLI::Success& done) {  // --help, --version
    return application.exit(done);
  } catch (const CLI::ParseError& usage) {
    // The same one line as every other bad input; the command's --help tells the rest.
    std::string help = "rbcsim";
    for (const CLI::App* level = &application; !level->get_subcommands().empty();) {
      level = level->get_subcommands().front();
      help += " " + level->get_name();
    }
    std::cerr << "rbcsim: error: " << usage.what() << " (see " << help << " --help)\n";
    return rbcsim::kExitBadInput;
  } catch (const rbcsim::InputError& bad_input) {
    std::cerr << "rbcsim: error: " << bad_input.what() << '\n';
    return rbcsim::kExitBadInput;
  } catch (const rbcsim::RuntimeFailure& failure) {
    std::cerr << "rbcsim: failed: " << failure.what() << '\n';
    return rbcsim::kExitRuntimeFailure;
  } catch (const rbcsim::Interrupted& interrupted) {
    std::cerr << "rbcsim: stopped: " << interrupted.what() << '\n';
    return rbcsim::kExitInterrupted;
  } catch (const std::exception& unexpected) {
    std::cerr << "rbcsim: internal error: " << unexpected.what() << '\n';
    return rbcsim::kExitRuntimeFailure;
  }
  return rbcsim::kExitSuccess;
}
