#include "bench_paper_cases.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iostream>

#include "bench_table.hpp"
#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/interrupt.hpp"

extern char** environ;

namespace rbcsim::cli {
namespace {

using Json = nlohmann::ordered_json;

// The cases "all" runs; capillary-fine (the 2562-vertex cell on dx 0.25 um) takes hours on two
// cores and runs only when named.
const std::vector<std::string> kDefaultCases = {"capillary", "mills", "shear"};

// The paper's pairing: the 2562-vertex cell on dx 0.5 um (Sec. 2.3), at §3.4's natural velocity.
const std::vector<std::string> kValidationCapillary = {"capillary", "--set",
                                                       "capillary.inlet_velocity_m_per_s=5e-4"};
// Before the speed work the capillary ran at the velocity it was given.
const std::vector<std::string> kUncompressed = {"--set", "capillary.time_scale_compression=false"};

std::vector<std::string> joined(std::vector<std::string> first,
                                const std::vector<std::string>& second) {
  first.insert(first.end(), second.begin(), second.end());
  return first;
}

std::string known_names(const std::vector<PaperCase>& cases) {
  std::string names = "all";
  for (const auto& paper_case : cases) names += ", " + paper_case.name;
  return names;
}

struct ChildOutcome {
  int exit_code = 0;  // 128 + the signal when a signal ended it
  double wall_s = 0.0;
};

// Runs this binary with `arguments`, stdout and stderr into `log`, behind `launcher` (e.g.
// {"/usr/bin/mpiexec", "-n", "2"}; empty: directly); waits for it.
ChildOutcome run_child(const std::vector<std::string>& launcher,
                       const std::vector<std::string>& arguments,
                       const std::filesystem::path& log) {
  const auto self = std::filesystem::read_symlink("/proc/self/exe");
  std::vector<std::string> words = launcher;
  words.push_back(self.string());
  words.insert(words.end(), arguments.begin(), arguments.end());
  const std::string executable = words.front();
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
  pid_t child = 0;
  const int spawned =
      posix_spawn(&child, executable.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    throw RuntimeFailure("bench: could not start " + executable + ": " + std::strerror(spawned));
  }
  // Polled, so that an interrupt of the bench alone (kill -INT, not the terminal's Ctrl-C, which
  // reaches both) is passed on and the case writes its results so far.
  int status = 0;
  bool passed_on = false;
  while (true) {
    const pid_t ended = waitpid(child, &status, WNOHANG);
    if (ended == child) break;
    if (ended < 0 && errno != EINTR) throw RuntimeFailure("bench: waiting for a paper case failed");
    if (interrupt_requested() && !passed_on) {
      kill(child, SIGINT);
      passed_on = true;
    }
    usleep(100000);
  }
  ChildOutcome outcome;
  outcome.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return outcome;
}

// One run of a case: the child's wall time, exit code, and result.json's status and headline.
Json measure_run(const std::vector<std::string>& launcher,
                 const std::vector<std::string>& arguments, const std::filesystem::path& directory,
                 bool progress) {
  if (progress) {
    std::cerr << "rbcsim bench: paper case:";
    for (const auto& word : launcher) std::cerr << ' ' << word;
    std::cerr << " rbcsim";
    for (const auto& word : arguments) std::cerr << ' ' << word;
    std::cerr << std::endl;
  }
  const auto log = directory.string() + ".log";
  const auto outcome = run_child(launcher, arguments, log);
  throw_if_interrupted();
  if (outcome.exit_code == kExitInterrupted || outcome.exit_code == 128 + SIGINT ||
      outcome.exit_code == 128 + SIGTERM) {
    throw Interrupted("a paper case was interrupted (see " + log + ")");
  }
  Json run = {{"seconds", outcome.wall_s},
              {"exit_code", outcome.exit_code},
              {"directory", directory.string()},
              {"status", nullptr},
              {"headline", nullptr}};
  std::ifstream result(directory / "result.json");
  if (result) {
    const auto parsed = Json::parse(result, nullptr, false);
    if (!parsed.is_discarded()) {
      run["status"] = parsed.value("status", Json(nullptr));
      run["headline"] = parsed.value("headline", Json(nullptr));
      // Where the coupled steps' time went, from commands that record it (capillary).
      run["phase_ms_per_step"] = parsed.value("phase_ms_per_step", Json(nullptr));
    }
  }
  return run;
}

std::string run_name(const std::string& name, int threads, bool before) {
  return name + "-" + std::to_string(threads) + "t" + (before ? "-before" : "");
}

// The command line of one run of a case: its settings, those of the run as before the speed work
// when `before`, the bench's forwarded options (so they win), the thread count and the directory.
std::vector<std::string> case_arguments(const PaperCase& paper_case,
                                        const PaperCaseRequest& request, bool before, int threads,
                                        const std::filesystem::path& directory) {
  auto arguments = paper_case.arguments;
  if (before) arguments = joined(arguments, paper_case.before_arguments);
  arguments = joined(arguments, request.forwarded_arguments);
  return joined(arguments, {"--threads", std::to_string(threads), "--output", directory.string()});
}

// The case on request.processes processes of one thread each, against its one-process,
// one-thread run `one` ("processes" of the case's entry).
Json measure_on_processes(const PaperCase& paper_case, const PaperCaseRequest& request,
                          const Json& one) {
  const auto directory =
      request.directory / (paper_case.name + "-" + std::to_string(request.processes) + "p");
  const std::vector<std::string> launcher = {request.mpiexec.string(), "-n",
                                             std::to_string(request.processes)};
  const Json measured =
      measure_run(launcher, case_arguments(paper_case, request, false, 1, directory), directory,
                  request.progress);
  Json run = {{"processes", request.processes},
              {"threads_per_process", 1},
              {"run", measured},
              {"speedup_over_one_process", nullptr},
              {"fraction_of_linear", nullptr},
              {"same_headline_as_one_process", measured["headline"] == one["headline"]}};
  if (measured["exit_code"] == 0 && one["exit_code"] == 0) {
    const double speedup = one["seconds"].get<double>() / measured["seconds"].get<double>();
    run["speedup_over_one_process"] = speedup;
    run["fraction_of_linear"] = speedup / request.processes;
  }
  return run;
}

std::string seconds_cell(const Json& run) {
  if (run.is_null()) return "-";
  const std::string seconds = fixed(run["seconds"].get<double>(), 1);
  return run["exit_code"] == 0 ? seconds : seconds + " (exit " + run["exit_code"].dump() + ")";
}

// The rows of the run on several processes, under the thread counts' table.
void print_processes(const Json& processes) {
  if (processes.is_null()) return;
  const auto& run = processes["run"];
  const std::string label = "  " + processes["processes"].dump() + " processes x 1 thread (s)";
  if (processes["speedup_over_one_process"].is_null()) {
    print_row(label, {seconds_cell(run)}, "no ratio: a run did not end with exit 0");
    return;
  }
  const bool same = processes["same_headline_as_one_process"].get<bool>();
  print_row(label, {seconds_cell(run)},
            fixed(processes["speedup_over_one_process"].get<double>(), 2) +
                "x one process of one thread, " +
                fixed(100.0 * processes["fraction_of_linear"].get<double>(), 0) + " % of linear; " +
                (same ? "the same headline" : "ANOTHER headline"));
}

}  // namespace

std::vector<PaperCase> paper_cases(const config::Config& discocyte) {
  // 642-vertex cells have edges twice the 2562-vertex cell's; k_link and k_area go as k / L0 (the
  // hexagonal patch test), so twice them keeps Table 2's moduli (docs/physics.md).
  const std::vector<std::string> table2_at_642 = {
      "--set",
      "mesh.subdivisions=3",
      "--set",
      "membrane.k_link_kBT=" + format_number(2.0 * discocyte.number("membrane.k_link_kBT")),
      "--set",
      "membrane.k_area_kBT=" + format_number(2.0 * discocyte.number("membrane.k_area_kBT"))};
  return {
      {"capillary", "validation capillary, discocyte, 2562 vertices on dx 0.5 um, 5e-4 m/s",
       "transit", joined(kValidationCapillary, {"--set", "lattice.spacing_um=0.5"}), kUncompressed},
      {"capillary-fine", "the same on dx 0.25 um (edges about one spacing; hours, only when named)",
       "transit", joined(kValidationCapillary, {"--set", "lattice.spacing_um=0.25"}),
       kUncompressed},
      {"mills",
       "fluid-coupled Mills curve (13 forces), discocyte, 642 vertices (Table 2's moduli) on dx "
       "0.75 um, each force from its quasi-static equilibrium (before: ramped)",
       "curve",
       joined({"stretch", "--mode", "fluid", "--set", "lattice.spacing_um=0.75", "--set",
               "stretch.fluid.warm_start=true"},
              table2_at_642),
       {"--set", "stretch.fluid.warm_start=false"}},
      {"shear",
       "1000 1/s to steady state, discocyte, 642 vertices (Table 2's moduli) on dx 0.5 um",
       "rate",
       joined({"shear", "--rates", "1000", "--set", "lattice.spacing_um=0.5"}, table2_at_642),
       {}},
  };
}

std::vector<std::string> parse_paper_case_names(std::string_view text) {
  const auto cases = paper_cases(config::resolve_config({.morphology = "discocyte"}));
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto end = std::min(text.find(',', start), text.size());
    const std::string name(text.substr(start, end - start));
    if (name == "all") {
      names.insert(names.end(), kDefaultCases.begin(), kDefaultCases.end());
    } else if (std::none_of(cases.begin(), cases.end(),
                            [&](const PaperCase& c) { return c.name == name; })) {
      throw InputError("--paper-cases",
                       "\"" + name + "\" is not a case (" + known_names(cases) + ")");
    } else {
      names.push_back(name);
    }
    start = end + 1;
  }
  return names;
}

Json run_paper_cases(const config::Config& discocyte, const PaperCaseRequest& request) {
  std::filesystem::create_directories(request.directory);
  const auto cases = paper_cases(discocyte);
  Json entries = Json::array();
  for (const auto& name : request.names) {
    const auto& paper_case = *std::find_if(cases.begin(), cases.end(),
                                           [&](const PaperCase& c) { return c.name == name; });
    Json runs = Json::array();
    for (const int threads : request.thread_counts) {
      const auto measure = [&](bool before) {
        const auto directory = request.directory / run_name(name, threads, before);
        return measure_run({}, case_arguments(paper_case, request, before, threads, directory),
                           directory, request.progress);
      };
      Json run = {
          {"threads", threads}, {"now", measure(false)}, {"before", nullptr}, {"speedup", nullptr}};
      if (!paper_case.before_arguments.empty()) {
        run["before"] = measure(true);
        run["speedup"] =
            run["before"]["seconds"].get<double>() / run["now"]["seconds"].get<double>();
      }
      runs.push_back(run);
    }
    Json processes = nullptr;
    if (request.processes > 1) {
      const auto one = std::find_if(runs.begin(), runs.end(),
                                    [](const Json& run) { return run["threads"] == 1; });
      processes = measure_on_processes(paper_case, request, (*one)["now"]);
    }
    std::string before_settings;
    for (const auto& word : paper_case.before_arguments) {
      if (word != "--set") before_settings += (before_settings.empty() ? "" : " ") + word;
    }
    entries.push_back({{"name", paper_case.name},
                       {"description", paper_case.description},
                       {"seconds_per", paper_case.figure},
                       {"arguments", paper_case.arguments},
                       {"before_settings", before_settings},
                       {"added_arguments", request.forwarded_arguments},
                       {"runs", runs},
                       {"processes", processes}});
  }
  return entries;
}

void print_paper_cases(const Json& entries) {
  std::printf("\npaper cases: wall seconds of the command as a user runs it\n");
  for (const auto& entry : entries) {
    const auto& runs = entry["runs"];
    std::vector<std::string> threads;
    for (const auto& run : runs)
      threads.push_back(std::to_string(run["threads"].get<int>()) + " thread(s)");
    print_row(
        entry["name"].get<std::string>() + ": s per " + entry["seconds_per"].get<std::string>(), {},
        "");
    std::printf("  %s\n", entry["description"].get<std::string>().c_str());
    print_row("", threads);
    std::vector<std::string> now;
    std::vector<std::string> before;
    std::vector<std::string> speedup;
    for (const auto& run : runs) {
      now.push_back(seconds_cell(run["now"]));
      before.push_back(seconds_cell(run["before"]));
      speedup.push_back(run["speedup"].is_null() ? "-"
                                                 : fixed(run["speedup"].get<double>(), 2) + "x");
    }
    print_row("  now (s)", now);
    const auto& before_settings = entry["before_settings"].get<std::string>();
    print_row("  before the speed work (s)", before,
              before_settings.empty() ? "no setting restores it: the gain is in the code"
                                      : "with " + before_settings);
    if (!before_settings.empty()) print_row("  speed-up", speedup);
    print_processes(entry["processes"]);
  }
}

}  // namespace rbcsim::cli
