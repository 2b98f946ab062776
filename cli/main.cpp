// rbcsim: entry point. Maps failures onto exit codes (README.md, "Exit codes"):
// 0 success, 1 runtime failure (instability, NaN), 2 bad input (usage, config, mesh), 130
// interrupted by SIGINT or SIGTERM (the results so far written). Under `mpirun -np N` (a build
// with RBCSIM_MPI) every process runs this: bad input, the same on every process, is printed once
// by rank 0; any other failure is printed by the process it happened on, prefixed with its rank,
// and stops every process of the run (MPI_Abort) with the same exit code.
#include <CLI/CLI.hpp>
#include <iostream>
#include <streambuf>
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

// Where the output of the processes other than rank 0 goes: they compute what rank 0 does.
class DiscardingBuffer : public std::streambuf {
 protected:
  int overflow(int character) override { return traits_type::not_eof(character); }
};

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
  // Rank 0 alone prints and writes files; the others keep stderr for their own failures.
  std::ostream error_line(std::cerr.rdbuf());
  if (!world.is_root()) {
    // Never destroyed: the standard streams may be flushed after main returns.
    static auto* const discarded = new DiscardingBuffer;
    std::cout.rdbuf(discarded);
    std::cerr.rdbuf(discarded);
    rbcsim::io::set_process_writes_files(false);
  }
  // Bad input: identical on every process, said once. Failures: said where they happen, and the
  // whole run stops, so that no process waits forever for one that has left.
  const auto bad_input = [&world, &error_line](const std::string& line) {
    if (world.is_root()) error_line << line << '\n';
    return rbcsim::kExitBadInput;
  };
  const auto failure = [&world, &error_line](const std::string& line, int code) {
    if (world.size() == 1) {
      error_line << line << '\n';
      return code;
    }
    error_line << "[rank " << world.rank() << "] " << line << std::endl;
    world.abort(code);
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
    return failure("rbcsim: failed: " + std::string(error.what()), rbcsim::kExitRuntimeFailure);
  } catch (const rbcsim::Interrupted& interrupted) {
    return failure("rbcsim: stopped: " + std::string(interrupted.what()), rbcsim::kExitInterrupted);
  } catch (const std::exception& unexpected) {
    return failure("rbcsim: internal error: " + std::string(unexpected.what()),
                   rbcsim::kExitRuntimeFailure);
  }
  return rbcsim::kExitSuccess;
}
