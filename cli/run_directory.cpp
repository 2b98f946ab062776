#include "run_directory.hpp"

#include <omp.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <ctime>
#include <iostream>
#include <set>
#include <span>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/wall_clock.hpp"
#include "common_options.hpp"
#include "config/config_sources.hpp"
#include "coupling/checkpoint.hpp"
#include "io/atomic_file.hpp"
#include "io/sha256.hpp"
#include "io/text_file.hpp"
#include "parallel/communicator.hpp"

namespace rbcsim::cli {
namespace {

// "2024-05-01T12:34:56Z" (ISO 8601) or, for directory names, "20240501T123456Z".
std::string utc_text(std::chrono::system_clock::time_point time, const char* format) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(time);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  std::array<char, 32> text{};
  const auto length = std::strftime(text.data(), text.size(), format, &utc);
  return std::string(text.data(), length);
}

// The wall time of the interrupted run in `directory` (its result.json; 0 without one, or if it
// was not interrupted).
double interrupted_wall_time_s(const std::filesystem::path& directory) {
  const auto file = directory / "result.json";
  if (!std::filesystem::exists(file)) return 0.0;
  const auto result = config::parse_json(io::read_text_file(file), file.string());
  if (result.value("status", std::string()) != "interrupted") return 0.0;
  const auto wall = result.find("wall_time_s");
  if (wall == result.end() || !wall->is_number()) {
    throw InputError(file.string(), "an interrupted run's result without a number wall_time_s");
  }
  return wall->get<double>();
}

// A key (dotted) at which the config a run was started with and the config of a command resuming
// it differ: its value in each, "absent" where it is missing.
struct ConfigDifference {
  std::string key;
  std::string started;
  std::string now;
};

std::string shown(const nlohmann::json& value) {
  constexpr std::size_t kLongest = 60;
  auto text = value.dump();
  if (text.size() > kLongest) text = text.substr(0, kLongest) + "...";
  return text;
}

// Every key at which the two trees differ, in sorted order.
void add_differences(const nlohmann::json& started, const nlohmann::json& now,
                     const std::string& key, std::vector<ConfigDifference>& differences) {
  if (!started.is_object() || !now.is_object()) {
    if (started != now) differences.push_back({key, shown(started), shown(now)});
    return;
  }
  std::set<std::string> keys;
  for (const auto& [name, value] : started.items()) keys.insert(name);
  for (const auto& [name, value] : now.items()) keys.insert(name);
  for (const auto& name : keys) {
    const auto child = key.empty() ? name : key + "." + name;
    const auto was = started.find(name);
    const auto is = now.find(name);
    if (was == started.end() || is == now.end()) {
      differences.push_back({child, was == started.end() ? "absent" : shown(*was),
                             is == now.end() ? "absent" : shown(*is)});
    } else {
      add_differences(*was, *is, child, differences);
    }
  }
}

// A resume continues the run only with the config it was started with (its checkpoint and
// finished parts carry that config's fingerprint); this names the first option that differs, so
// the user need not guess which of the original command's options is missing.
void require_the_started_config(const std::filesystem::path& directory,
                                const config::Config& config) {
  const auto file = directory / "config.json";
  if (!std::filesystem::exists(file)) return;  // never started: the checkpoint's own check
  auto started = config::parse_json(io::read_text_file(file), file.string());
  started.erase("run");      // the record of the command that wrote it, not config
  started.erase("derived");  // follows from the rest
  std::vector<ConfigDifference> differences;
  add_differences(started, config.json(), "", differences);
  if (differences.empty()) return;
  const auto& first = differences.front();
  std::string message = "the run was started with " + first.key + " = " + first.started +
                        ", this command gives " + first.now;
  if (differences.size() > 1) {
    message += " (and " + std::to_string(differences.size() - 1) + " more keys differ)";
  }
  throw InputError(file.string(), message + ": resume with the options it was started with");
}

int apply_threads(int requested) {
  if (requested > 0) omp_set_num_threads(requested);
  return omp_get_max_threads();
}

}  // namespace

std::string mesh_sha256(const mesh::TriangleMesh& mesh) {
  io::Sha256 hash;
  hash.update(std::as_bytes(std::span(mesh.positions_um)));
  hash.update(std::as_bytes(std::span(mesh.triangles)));
  return hash.hex_digest();
}

RunDirectory::RunDirectory(std::string command, const CommonOptions& options,
                           const config::Config& config)
    : command_(std::move(command)),
      morphology_(config.string("morphology")),
      threads_(apply_threads(options.threads)),
      started_(WallClock::now()) {
  // Rank 0's clock on every process of a run across processes: one default directory name.
  double seconds =
      static_cast<double>(std::chrono::system_clock::to_time_t(std::chrono::system_clock::now()));
  parallel::Communicator::world().broadcast_from_root(std::span<double>(&seconds, 1));
  const auto now = std::chrono::system_clock::from_time_t(static_cast<std::time_t>(seconds));
  started_utc_ = utc_text(now, "%Y-%m-%dT%H:%M:%SZ");
  path_ = !options.output_directory.empty()
              ? options.output_directory
              : std::filesystem::path("runs") /
                    (command_ + "-" + morphology_ + "-" + utc_text(now, "%Y%m%dT%H%M%SZ"));
  if (options.resuming) {
    require_the_started_config(path_, config);
    wall_time_before_resume_s_ = interrupted_wall_time_s(path_);
  }
}

double RunDirectory::elapsed_s() const { return seconds_since(started_); }

void RunDirectory::start(const config::Config& config, const setup::CellMesh& cell) const {
  std::error_code error;
  // Only the process that writes files makes the directory (main.cpp stops the run if it fails).
  if (io::process_writes_files()) std::filesystem::create_directories(path_, error);
  if (io::process_writes_files() && (error || !std::filesystem::is_directory(path_))) {
    throw InputError(path_.string(), "cannot create the run directory" +
                                         (error ? ": " + error.message() : std::string()));
  }
  auto content = config::config_with_derived_values(config);
  content["run"] = {{"command", command_},        {"version", RBCSIM_VERSION},
                    {"mesh_source", cell.source}, {"mesh_sha256", mesh_sha256(cell.mesh)},
                    {"threads", threads_},        {"started_utc", started_utc_},
                    {"notices", cell.run_notices}};
  io::write_text_atomically(
      path_ / "config.json",
      content.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  print_notices(cell.run_notices);
}

nlohmann::ordered_json RunDirectory::result_head(bool ok) const {
  return result_head_with_status(ok ? "ok" : "failed");
}

nlohmann::ordered_json RunDirectory::result_head_with_status(std::string_view status) const {
  nlohmann::ordered_json head = {{"command", command_},
                                 {"version", RBCSIM_VERSION},
                                 {"morphology", morphology_},
                                 {"status", status},
                                 {"wall_time_s", wall_time_before_resume_s_ + elapsed_s()},
                                 {"threads", threads_}};
  if (wall_time_before_resume_s_ > 0.0) {
    head["wall_time_before_resume_s"] = wall_time_before_resume_s_;
  }
  return head;
}

void RunDirectory::write_json(const std::string& file_name,
                              const nlohmann::ordered_json& content) const {
  io::write_text_atomically(path_ / file_name, content.dump(2) + "\n");
}

std::string config_fingerprint(const config::Config& config) {
  io::Sha256 fingerprint;
  const auto tree = config.json().dump();
  fingerprint.update(std::as_bytes(std::span(tree.data(), tree.size())));
  return fingerprint.hex_digest();
}

void write_finished_record(const std::filesystem::path& file, nlohmann::ordered_json record,
                           const std::string& fingerprint) {
  record["config_sha256"] = fingerprint;
  io::write_text_atomically(file, record.dump(2) + "\n");
}

std::optional<nlohmann::json> read_finished_record(const std::filesystem::path& file,
                                                   const std::string& fingerprint) {
  if (!std::filesystem::exists(file)) return std::nullopt;
  auto record = config::parse_json(io::read_text_file(file), file.string());
  if (record.value("config_sha256", std::string()) != fingerprint) {
    throw InputError(file.string(), "written by a run with a different config");
  }
  return record;
}

namespace {

void set_checkpoint_file(coupling::CoupledSimulation& simulation, const CheckpointOptions& options,
                         const std::filesystem::path& file, const config::Config& config) {
  const auto interval =
      options.every.empty() ? CheckpointInterval{} : parse_checkpoint_interval(options.every);
  simulation.set_checkpoint_policy(
      {file, config_fingerprint(config), interval.steps, interval.wall_s});
}

}  // namespace

void wire_checkpoints(coupling::CoupledSimulation& simulation, const CheckpointOptions& options,
                      const RunDirectory& directory, const config::Config& config) {
  set_checkpoint_file(simulation, options, directory.path() / coupling::kCheckpointFileName,
                      config);
  if (!options.resume_directory.empty()) {
    simulation.resume_from(options.resume_directory / coupling::kCheckpointFileName);
  }
}

void wire_checkpoints_in(const std::filesystem::path& subdirectory,
                         coupling::CoupledSimulation& simulation, const CheckpointOptions& options,
                         const RunDirectory& directory, const config::Config& config) {
  const auto file = directory.path() / subdirectory / coupling::kCheckpointFileName;
  if (io::process_writes_files()) std::filesystem::create_directories(file.parent_path());
  set_checkpoint_file(simulation, options, file, config);
  // Across processes all resume if any sees the file (resume_from then agrees on reading it).
  if (!options.resume_directory.empty() &&
      parallel::Communicator::world().any(std::filesystem::exists(file))) {
    simulation.resume_from(file);
  }
}

std::string summary_heading(const std::string& command, const std::string& variant,
                            const nlohmann::ordered_json& result) {
  std::string heading = command;
  heading.append(" (").append(variant).append("), ");
  heading.append(result["morphology"].get<std::string>()).append(", terms:");
  for (const auto& term : result[command]["forces_terms"]) {
    heading.append(" ").append(term.get<std::string>());
  }
  return heading;
}

std::string WallTimeLeft::text(double measure, double wall_s) {
  if (!first_) first_ = ProgressPoint{measure, wall_s};
  const auto left_s = wall_time_left_s(*first_, {measure, wall_s}, total_);
  return left_s ? ", about " + format_number(std::round(*left_s)) + " s left" : "";
}

Progress::Progress(const CommonOptions& options)
    : terminal_(!options.quiet && isatty(STDERR_FILENO) == 1),
      log_(!terminal_ && options.verbose) {}

void Progress::update(const std::string& line) const {
  if (terminal_) std::cerr << "\r\033[K" << line << std::flush;
  if (!log_) return;
  const auto now = std::chrono::steady_clock::now();
  if (last_logged_ && std::chrono::duration<double>(now - *last_logged_).count() < kLogIntervalS) {
    return;
  }
  last_logged_ = now;
  std::cerr << line << '\n' << std::flush;
}

void Progress::done() const {
  if (terminal_) std::cerr << "\r\033[K" << std::flush;
}

}  // namespace rbcsim::cli
