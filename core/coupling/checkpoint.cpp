#include "coupling/checkpoint.hpp"

#include "common/state_archive.hpp"
#include "coupling/coupled_simulation.hpp"
#include "io/state_archive_file.hpp"

namespace rbcsim::coupling {

void write_checkpoint(const std::filesystem::path& file, const CoupledSimulation& simulation,
                      std::string_view config_fingerprint) {
  StateArchive archive;
  simulation.save_state(archive);
  io::write_state_archive(file, archive, kCheckpointVersion, config_fingerprint);
}

void read_checkpoint(const std::filesystem::path& file, CoupledSimulation& simulation,
                     std::string_view config_fingerprint) {
  StateArchive archive = io::read_state_archive(file, kCheckpointVersion, config_fingerprint);
  simulation.restore_state(archive);
  archive.require_all_taken();
}

}  // namespace rbcsim::coupling
