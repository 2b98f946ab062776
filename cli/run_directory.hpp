// The run directory every experiment command writes (calibrate, stretch, shear, capillary), and
// that `rbcsim report` reads:
//   config.json  the resolved config with its "derived" values, plus a "run" object: command,
//                version, mesh_source, mesh_sha256, threads, started_utc, notices;
//   result.json  command, version, morphology, status ("ok" | "failed" | "interrupted"),
//                wall_time_s, threads, headline, files, and the command's own object
//                (schemas/result.schema.json). A resumed run's wall_time_s adds the time of the
//                interrupted run it continues (wall_time_before_resume_s: that run's
//                result.json, itself cumulative); a run killed without writing one adds nothing;
//   CSV tables and ParaView files of the command.
// Every file is written atomically (io/atomic_file.hpp).
#pragma once

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "common/wall_clock.hpp"
#include "common_options.hpp"
#include "config/config.hpp"
#include "coupling/coupled_simulation.hpp"
#include "setup/cell_from_config.hpp"

namespace rbcsim::cli {

// SHA-256 of the mesh's vertex array (x, y, z as float64) followed by its triangle array (three
// int32 each), as laid out in memory (little-endian): equal for equal meshes, whatever file or
// generator they came from.
std::string mesh_sha256(const mesh::TriangleMesh& mesh);

class RunDirectory {
 public:
  // Applies --threads (OpenMP) and notes the start time. The directory is --output, or
  // runs/<command>-<morphology>-<UTC timestamp> below the working directory. With --resume,
  // refuses a config other than the one in the directory's config.json (InputError naming the
  // first key that differs) and reads the wall time of the interrupted run from its result.json
  // (InputError if unreadable).
  RunDirectory(std::string command, const CommonOptions& options, const config::Config& config);

  const std::filesystem::path& path() const { return path_; }
  int threads() const { return threads_; }
  double elapsed_s() const;  // of this process's run

  // Creates the directory (InputError if that fails), writes config.json and tells the cell's
  // run notices (stderr, and config.json's "run" object).
  void start(const config::Config& config, const setup::CellMesh& cell) const;
  // command, version, morphology, status, wall_time_s, threads: the head of result.json.
  nlohmann::ordered_json result_head(bool ok) const;
  // The same with status "ok", "failed" or "interrupted" (by a signal, the results so far).
  nlohmann::ordered_json result_head_with_status(std::string_view status) const;
  // <directory>/<file_name>, pretty-printed.
  void write_json(const std::string& file_name, const nlohmann::ordered_json& content) const;

 private:
  std::string command_;
  std::string morphology_;
  std::filesystem::path path_;
  int threads_ = 1;
  std::string started_utc_;
  WallClock::time_point started_;
  double wall_time_before_resume_s_ = 0.0;
};

// The checkpoints of a coupled run (coupling/checkpoint.hpp): sets the simulation's policy
// (<run dir>/checkpoint.bin, the SHA-256 of the resolved config as fingerprint, the
// --checkpoint-every interval) and, with --resume, loads the checkpoint of that directory (the run
// directory itself). Call it after the cells, observers and stop criteria are added, before run().
void wire_checkpoints(coupling::CoupledSimulation& simulation, const CheckpointOptions& options,
                      const RunDirectory& directory, const config::Config& config);

// The same for one of several simulations of a run, each with its checkpoint in its own
// subdirectory of the run directory (shear's rate_<i>/, created here): with --resume, a
// subdirectory without a checkpoint holds a simulation that had not started, which starts afresh.
void wire_checkpoints_in(const std::filesystem::path& subdirectory,
                         coupling::CoupledSimulation& simulation, const CheckpointOptions& options,
                         const RunDirectory& directory, const config::Config& config);

// The SHA-256 of the resolved config: what a checkpoint and a resume must agree on.
std::string config_fingerprint(const config::Config& config);

// What a part of a run that ended keeps for --resume, so that it is not run again: shear's
// rate_<i>/point.json, one cell's point or a suspension's whole run.
constexpr const char* kRatePointFileName = "point.json";
// Writes `record` with the config's fingerprint ("config_sha256"), atomically.
void write_finished_record(const std::filesystem::path& file, nlohmann::ordered_json record,
                           const std::string& fingerprint);
// The record in `file`, or nothing when there is none. InputError naming the file when it
// cannot be parsed or was written under another config.
std::optional<nlohmann::json> read_finished_record(const std::filesystem::path& file,
                                                   const std::string& fingerprint);

// The heading of a command's printed summary: "<command> (<variant>), <morphology>, terms: <the
// enabled membrane terms>", the terms from the command's result section ("forces_terms").
std::string summary_heading(const std::string& command, const std::string& variant,
                            const nlohmann::ordered_json& result);

// The wall time left of one coupled run for its progress lines, extrapolated (wall_time_left_s)
// from the first point it is shown, so that the rate is the run's own and not its set-up's.
class WallTimeLeft {
 public:
  explicit WallTimeLeft(double total) : total_(total) {}
  // ", about N s left" at `measure` after `wall_s`, or "" before the run has moved.
  std::string text(double measure, double wall_s);

 private:
  double total_;
  std::optional<ProgressPoint> first_;
};

// Progress on stderr (docs/architecture.md: results go to files and stdout, so pipelines
// never see progress). On a terminal, unless --quiet: one line, overwritten. Otherwise only with
// --verbose, for runs of hours logged to a file: whole lines, the first at once and then at most
// one per kLogIntervalS (a capillary run updates every kProgressIntervalSteps steps).
class Progress {
 public:
  static constexpr double kLogIntervalS = 30.0;

  explicit Progress(const CommonOptions& options);
  void update(const std::string& line) const;
  void done() const;  // ends the terminal's line

 private:
  bool terminal_ = false;
  bool log_ = false;
  mutable std::optional<std::chrono::steady_clock::time_point> last_logged_;
};

}  // namespace rbcsim::cli
