// rbcsim: entry point. Maps failures onto exit codes (README.md, "Exit codes"):
// 0 success, 1 runtime failure (instability, NaN), 2 bad input (usage, config, mesh), 130
// interrupted by SIGINT or SIGTERM (the results so far written). Under `mpirun -np N` (a build
// with RBCSIM_MPI) every process runs this and only rank 0 prints and writes files. A failure that
// ends the command on every process (results, checks and bad input are the same everywhere) is
// printed once by rank 0 and every process exits with its code; a failure of some processes only
// is printed by each, prefixed with its rank, and stops the whole run (MPI_Abort) with its code.
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <string>

#include "command_registry.hpp"
#include "common/errors.hpp"
#include "common/interrupt.hpp"
#include "io/atomic_file.hpp"
#include "parallel/communicator.hpp"

namespace {

// Commands that do not run on several processes yet are refused before they start.
void refuse_on_several_processes(CLI::App& command, int processes) {
  command.preparse_callback([name = command.get_name(), processes](std::size_t) {
    throw rbcsim::InputError(
        "rbcsim " + name,
        "runs on one process only, not yet under mpirun (" + std::to_string(processes) +
            " processes started); shear, stretch --mode fluid, capillary and bench --ranks "
            "do");
  });
}

// How long the processes that failed wait for the others before deciding that they failed alone:
// rank 0 may still be writing the results the others computed too.
constexpr double kFailureAgreementSeconds = 60.0;

}  // namespace

int main(int argc, char** argv) {
  if (!rbcsim::parallel::built_with_mpi() && rbcsim::parallel::launcher_process_count() > 1) {
    std::cerr << "rbcsim: error: started as one of " << rbcsim::parallel::launcher_process_count()
              << " MPI processes, but this rbcsim was built without MPI (configure with "
                 "-DRBCSIM_MPI=ON)\n";
    return rbcsim::kExitBadInput;
  }
  const rbcsim::parallel::MpiSession mpi(argc, argv);
  const auto world = rbcsim::parallel::Communicator::world();
  // Rank 0 alone prints and writes files; the others keep a copy of stderr for failures of their
  // own (std::cout and std::cerr follow stdout and stderr: synchronised with stdio).
  FILE* errors = stderr;
  if (!world.is_root()) {
    const int copy = ::dup(STDERR_FILENO);
    if (copy >= 0) errors = ::fdopen(copy, "w");
    if (errors == nullptr) errors = stderr;
    std::fflush(stdout);
    std::fflush(stderr);
    if (std::freopen("/dev/null", "w", stdout) == nullptr ||
        (errors != stderr && std::freopen("/dev/null", "w", stderr) == nullptr)) {
      std::fprintf(errors, "[rank %d] rbcsim: cannot silence this process's output\n",
                   world.rank());
    }
    rbcsim::io::set_process_writes_files(false);
  }
  const auto finish = [&world, errors](const std::string& line, int code) {
    if (world.size() == 1) {
      std::fprintf(errors, "%s\n", line.c_str());
      return code;
    }
    if (rbcsim::parallel::every_process_fails_together(kFailureAgreementSeconds)) {
      if (world.is_root()) std::fprintf(errors, "%s\n", line.c_str());
      return code;
    }
    std::fprintf(errors, "[rank %d] %s\n", world.rank(), line.c_str());
    std::fflush(errors);
    world.abort(code);
  };
  const auto bad_input = [&finish](const std::string& line) {
    return finish(line, rbcsim::kExitBadInput);
  };
  CLI::App application{
      "rbcsim — red blood cells (discocyte, stomatocyte II, echinocyte III) stretched, sheared\n"
      "and squeezed through capillaries: D3Q19 lattice Boltzmann plasma, six-force membrane,\n"
      "immersed-boundary coupling.",
      "rbcsim"};
  application.set_version_flag("--version", std::string("rbcsim ") + RBCSIM_VERSION);
  application.require_subcommand(1);
  for (const auto& command : rbcsim::cli::registered_commands()) {
    command.attach(application);
    if (world.size() > 1 && !command.runs_on_processes) {
      refuse_on_several_processes(*application.get_subcommand(command.name), world.size());
    }
  }

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
    return bad_input("rbcsim: error: " + std::string(usage.what()) + " (see " + help + " --help)");
  } catch (const rbcsim::InputError& error) {
    return bad_input("rbcsim: error: " + std::string(error.what()));
  } catch (const rbcsim::RuntimeFailure& error) {
    return finish("rbcsim: failed: " + std::string(error.what()), rbcsim::kExitRuntimeFailure);
  } catch (const rbcsim::Interrupted& interrupted) {
    return finish("rbcsim: stopped: " + std::string(interrupted.what()), rbcsim::kExitInterrupted);
  } catch (const std::exception& unexpected) {
    return finish("rbcsim: internal error: " + std::string(unexpected.what()),
                  rbcsim::kExitRuntimeFailure);
  }
  return rbcsim::kExitSuccess;
}
