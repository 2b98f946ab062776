// Checkpoint files of a coupled simulation (docs/architecture.md: long runs checkpoint and resume).
//
// The file's layout: io/state_archive_file.hpp, version kCheckpointVersion. The arrays are
// CoupledSimulation::save_state's (common/state_archive.hpp): fluid populations as the kernel holds
// them and their layout (natural or AA-swapped), density, velocity, step counts, every cell's
// positions and point-advance history, the force-cap monitors and the stop criteria's memory.
// Written atomically (io/atomic_file.hpp); a kill during the write leaves the previous checkpoint
// intact.
//
// Reading refuses (InputError, exit 2, one line naming the file) a file that is not a
// checkpoint, of another version, truncated or corrupted (checksum), written under another
// config (fingerprint), or whose arrays do not fit the simulation it is loaded into.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rbcsim::coupling {

class CoupledSimulation;

// Version 4: the simulation's count of steps with a near contact between cells.
// Version 3: a capillary sample holds its area strain too (12 numbers, version 2: 10).
// Version 2: the populations are stored in the kernel's layout (version 1: streamed to natural).
inline constexpr std::uint32_t kCheckpointVersion = 4;
inline constexpr const char* kCheckpointFileName = "checkpoint.bin";

void write_checkpoint(const std::filesystem::path& file, const CoupledSimulation& simulation,
                      std::string_view config_fingerprint);

// Loads `file` into `simulation`, built from the same config with the same cells, observers and
// stop criteria, before its first step.
void read_checkpoint(const std::filesystem::path& file, CoupledSimulation& simulation,
                     std::string_view config_fingerprint);

}  // namespace rbcsim::coupling
