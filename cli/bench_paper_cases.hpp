// `rbcsim bench --paper-cases`: the paper's runs as a user runs them, timed end to end
// (docs/commands/bench.md). Each case is an rbcsim command with its settings, run as a child
// process of this binary with --threads 1 and with all threads (and, on request, under mpiexec on
// several processes of one thread); where a setting restores how the case ran before the speed
// work (time-scale compression off, say), the case also runs with it, side by side, and the ratio
// of the two is the speed-up on this machine. Without such a setting the speed-up lives in the
// code and there is nothing to run it against: no ratio is printed.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "config/config.hpp"

namespace rbcsim::cli {

struct PaperCase {
  std::string name;         // what --paper-cases takes: "capillary"
  std::string description;  // what runs, with its resolution
  std::string figure;       // what the seconds are per: "transit"
  // The command and its settings, e.g. {"capillary", "--set", "..."}.
  std::vector<std::string> arguments;
  // Appended for the run as before the speed work; empty: no setting brings it back.
  std::vector<std::string> before_arguments;
};

// Every case the bench knows, the ones run by "all" marked in the description; `discocyte` is
// the resolved configuration of the discocyte (its Table 2 moduli set the 642-vertex cells').
std::vector<PaperCase> paper_cases(const config::Config& discocyte);

// "all" or a comma-separated list of case names, in the order given; InputError naming
// --paper-cases (with the names it takes) otherwise.
std::vector<std::string> parse_paper_case_names(std::string_view text);

struct PaperCaseRequest {
  std::vector<std::string> names;
  std::vector<int> thread_counts;
  // The bench's own --config, --preset and --set, appended to each case's settings (so they win).
  std::vector<std::string> forwarded_arguments;
  // Where each run's directory goes (<case>-<threads>t[-before]); kept.
  std::filesystem::path directory;
  bool progress = true;  // one line on stderr per run
  // Above 1: each case also runs as `mpiexec -n processes rbcsim ...`, one thread per process
  // (<case>-<processes>p), timed against its one-process, one-thread run.
  int processes = 1;
  std::filesystem::path mpiexec;  // the launcher, when processes > 1
};

// Runs the cases; one JSON entry per case: name, description, figure, the command, and per thread
// count the wall seconds, exit code, status and headline of result.json, and those of the run as
// before with the ratio; with request.processes > 1 also "processes": that run and its speed-up
// over one process of one thread, and the fraction of linear. An interrupt (the child's or ours)
// throws Interrupted.
nlohmann::ordered_json run_paper_cases(const config::Config& discocyte,
                                       const PaperCaseRequest& request);

// The text table of run_paper_cases' entries.
void print_paper_cases(const nlohmann::ordered_json& entries);

}  // namespace rbcsim::cli
