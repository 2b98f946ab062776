// rbcsim bench [--json] [--threads N] [--verbose]: what this machine and this build achieve
// (docs/performance.md), in one run — memory bandwidth (STREAM triad), fluid-only MLUPS on
// HemoCell's 40x40x20 lattice and on one far beyond the last-level cache, the fraction of the DRAM
// roofline, and ms per coupled step with a 642- and a 2562-vertex cell — for one thread and for
// all, with ratios to a reference measured on a named machine (bench_reference.hpp; HemoCell side
// by side on the project machine unless --reference FILE), and ms per step of suspensions of 1 to
// 100 cells with the share of each phase. Wall-clock measurements: other load lowers them, so the
// machine's load average is printed with them.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bench_paper_cases.hpp"
#include "bench_ranks.hpp"
#include "bench_reference.hpp"
#include "bench_table.hpp"
#include "command_registry.hpp"
#include "common/errors.hpp"
#include "common_options.hpp"
#include "contact/cell_repulsion.hpp"
#include "coupling/benchmark.hpp"
#include "io/atomic_file.hpp"
#include "lattice/benchmark.hpp"
#include "lattice/d3q19.hpp"
#include "mesh/cell_shapes.hpp"
#include "parallel/communicator.hpp"
#include "setup/cell_from_config.hpp"
#include "setup/membrane_from_config.hpp"

namespace rbcsim::cli::bench_command {
namespace {

using Json = nlohmann::ordered_json;

// The targets of the issue: >= 80 % of the DRAM roofline on the large lattice; a coupled step
// (642 vertices, phi2, one core) 20x faster than HemoCell's, i.e. <= 0.6 ms.
constexpr double kRooflineTarget = 0.8;
constexpr double kCoupledTargetMsOneCore = 0.6;
// Bytes moved per node update by a double-precision D3Q19 kernel: 19 populations read and written.
constexpr double kBytesPerNodeUpdate = 2.0 * lattice::kDirections * sizeof(double);

const std::array<int, 3> kHemoCellLattice = {40, 40, 20};
// Icosphere levels of the two cells (the configured morphology): 642 and 2562 vertices.
constexpr std::array<int, 2> kCellLevels = {3, 4};
// Steps per fluid measurement and repetitions (the best counts). On the small lattice a step takes
// about a millisecond, so short runs, many times, catch moments free of other load, as the
// fastest batch does for the coupled step; the reference kernel sets the cost of each repetition.
constexpr std::size_t kSmallLatticeSteps = 5;
constexpr int kSmallLatticeRepetitions = 10;
constexpr std::size_t kLargeLatticeSteps = 1;
// Cells in the suspensions measured (642 vertices each) unless --cells.
const std::vector<int> kDefaultSuspensionCellCounts = {1, 10, 50, 100};
// Each triad array at least this large, and at least the last-level cache.
constexpr std::size_t kMinimumTriadBytes = std::size_t{64} << 20;

struct BenchOptions {
  CommonOptions common;
  std::vector<int> large_lattice;
  std::vector<int> suspension_cell_counts = kDefaultSuspensionCellCounts;
  std::optional<std::filesystem::path> reference_file;
  std::string paper_cases;  // --paper-cases: empty, "all" or names
  bool ranks = false;       // --ranks: the distributed lattice only
  std::vector<int> rank_lattice = {128, 128, 128};  // --ranks-lattice
  int block_planes = 8;                             // --block-planes
  int rank_cells = 8;                               // --ranks-cells
  int paper_case_processes = 1;                     // --paper-cases-processes
};

// figure / ours for a time, ours / figure for a throughput: > 1 when rbcsim is faster.
Json ratio_or_null(const std::optional<double>& reference, double ours, bool time) {
  if (!reference) return nullptr;
  return time ? *reference / ours : ours / *reference;
}

std::string lattice_name(const std::array<int, 3>& extent) {
  return std::to_string(extent[0]) + "x" + std::to_string(extent[1]) + "x" +
         std::to_string(extent[2]);
}

lattice::FluidThroughput best_fluid_throughput(const std::array<int, 3>& extent, std::size_t steps,
                                               int repetitions, int threads) {
  lattice::FluidThroughput best;
  for (int r = 0; r < repetitions; ++r) {
    const auto measured =
        lattice::measure_fluid_mlups(extent[0], extent[1], extent[2], steps, threads);
    best.optimised_mlups = std::max(best.optimised_mlups, measured.optimised_mlups);
    best.reference_mlups = std::max(best.reference_mlups, measured.reference_mlups);
    best.single_mlups = std::max(best.single_mlups, measured.single_mlups);
  }
  return best;
}

Json fluid_entry(const std::array<int, 3>& extent, const lattice::FluidThroughput& throughput,
                 double roofline_mlups, int threads, const BenchReference& reference) {
  const bool comparable = extent == kHemoCellLattice;
  return {{"lattice", extent},
          {"optimised_mlups", throughput.optimised_mlups},
          {"reference_mlups", throughput.reference_mlups},
          {"optimised_over_reference", throughput.optimised_mlups / throughput.reference_mlups},
          {"roofline_fraction", throughput.optimised_mlups / roofline_mlups},
          {"single_mlups", throughput.single_mlups},
          {"single_over_double", throughput.single_mlups / throughput.optimised_mlups},
          // Single precision moves half the population bytes: its roofline is twice as high.
          {"single_roofline_fraction", throughput.single_mlups / (2.0 * roofline_mlups)},
          {"speedup_vs_reference", comparable ? ratio_or_null(reference.fluid_mlups(threads),
                                                              throughput.optimised_mlups, false)
                                              : Json(nullptr)}};
}

Json phases_json(const coupling::StepPhaseTimes& phases) {
  Json json = Json::object();
  for (const auto& [phase, ms] : coupling::ms_per_step_by_phase(phases)) json[phase] = ms;
  return json;
}

Json coupled_entry(const coupling::CoupledStepTiming& timing, int threads,
                   const BenchReference& reference) {
  Json entry = {{"vertices", timing.vertex_count},
                {"ms_per_step", timing.ms_per_step},
                {"phases_ms_per_step", phases_json(timing.fastest_batch_phases)}};
  // The reference's figures are for the 642-vertex cell.
  entry["speedup_vs_reference"] =
      timing.vertex_count == 642
          ? ratio_or_null(reference.coupled_ms(threads), timing.ms_per_step, true)
          : Json(nullptr);
  return entry;
}

// The share of the step's measured phases in the four the suspension's cost is made of; the
// membrane is its forces plus, with membrane viscosity, its friction solve; the IBM is spreading
// plus interpolation and advance; the rest (cytoplasm indicator, checks, observers) is "other".
Json suspension_shares(const coupling::StepPhaseTimes& phases) {
  const double total = phases.total_s();
  const double membrane = phases.membrane_s + phases.friction_s;
  const double ibm = phases.spread_s + phases.advance_s;
  return {{"fluid", phases.fluid_s / total},
          {"membrane", membrane / total},
          {"ibm", ibm / total},
          {"contact", phases.contact_s / total},
          {"other", 1.0 - (phases.fluid_s + membrane + ibm + phases.contact_s) / total}};
}

// ms per step per cell against one cell's in the same run: 1 when the cost is linear in the cells.
Json suspension_entries(const std::vector<coupling::SuspensionStepTiming>& timings) {
  Json entries = Json::array();
  const double one_cell_ms =
      timings.front().ms_per_step / static_cast<double>(timings.front().cell_count);
  for (const auto& timing : timings) {
    const double per_cell_ms = timing.ms_per_step / static_cast<double>(timing.cell_count);
    entries.push_back({{"cells", timing.cell_count},
                       {"vertices", timing.vertex_count},
                       {"lattice", timing.lattice},
                       {"contact_pairs", timing.contact_pairs},
                       {"ms_per_step", timing.ms_per_step},
                       {"ms_per_step_per_cell", per_cell_ms},
                       {"per_cell_over_fewest_cells", per_cell_ms / one_cell_ms},
                       {"shares", suspension_shares(timing.fastest_batch_phases)},
                       {"phases_ms_per_step", phases_json(timing.fastest_batch_phases)}});
  }
  return entries;
}

struct BenchSetup {
  std::vector<mesh::TriangleMesh> cells;
  contact::ContactParameters contact;
  std::vector<int> suspension_cell_counts;
  membrane::MembraneParameters membrane;
  std::optional<units::UnitConverter> units;  // has no default state
  std::string ibm_kernel;
  coupling::CytoplasmSettings cytoplasm;
  std::array<int, 3> large_lattice;
  std::size_t triad_elements;
  BenchReference reference;
};

Json measure_at(int threads, const BenchSetup& setup) {
  const double bandwidth =
      coupling::measure_triad_bandwidth_GB_per_s(setup.triad_elements, threads);
  const double roofline_mlups = bandwidth * 1e9 / kBytesPerNodeUpdate / 1e6;
  Json fluid = Json::array();
  fluid.push_back(fluid_entry(kHemoCellLattice,
                              best_fluid_throughput(kHemoCellLattice, kSmallLatticeSteps,
                                                    kSmallLatticeRepetitions, threads),
                              roofline_mlups, threads, setup.reference));
  fluid.push_back(
      fluid_entry(setup.large_lattice,
                  best_fluid_throughput(setup.large_lattice, kLargeLatticeSteps, 1, threads),
                  roofline_mlups, threads, setup.reference));
  Json coupled = Json::array();
  for (const auto& cell : setup.cells) {
    coupled.push_back(coupled_entry(
        coupling::measure_coupled_step(cell, setup.membrane, *setup.units, kHemoCellLattice,
                                       setup.ibm_kernel, threads, setup.cytoplasm),
        threads, setup.reference));
  }
  std::vector<coupling::SuspensionStepTiming> suspensions;
  for (const int count : setup.suspension_cell_counts) {
    suspensions.push_back(coupling::measure_suspension_step(
        setup.cells.front(), setup.membrane, *setup.units, setup.contact,
        static_cast<std::size_t>(count), setup.ibm_kernel, threads));
  }
  return {{"threads", threads},
          {"memory_bandwidth_GB_per_s", bandwidth},
          {"roofline_mlups", roofline_mlups},
          {"fluid", fluid},
          {"coupled", coupled},
          {"suspension", suspension_entries(suspensions)}};
}

BenchSetup bench_setup(const BenchOptions& options, const coupling::MachineDescription& machine) {
  const auto config = resolve_config(options.common);
  BenchSetup setup;
  for (const int level : kCellLevels) {
    setup.cells.push_back(mesh::generate_cell(config.string("morphology"), level,
                                              setup::cell_shape_parameters_from(config)));
  }
  setup.membrane = setup::membrane_parameters_from(config);
  setup.contact = {config.number("suspension.contact_force_pN"),
                   config.number("suspension.contact_range_um")};
  setup.suspension_cell_counts = options.suspension_cell_counts;
  std::sort(setup.suspension_cell_counts.begin(), setup.suspension_cell_counts.end());
  setup.units.emplace(config::make_unit_converter(config));
  setup.ibm_kernel = config.string("ibm.kernel");
  setup.cytoplasm = {config.number("physics.cytoplasm_viscosity_ratio"),
                     config.number("ibm.cytoplasm_update_dx")};
  setup.large_lattice = options.large_lattice.size() == 3
                            ? std::array<int, 3>{options.large_lattice[0], options.large_lattice[1],
                                                 options.large_lattice[2]}
                            : coupling::lattice_beyond_cache(machine.last_level_cache_bytes);
  setup.triad_elements =
      std::max(kMinimumTriadBytes, machine.last_level_cache_bytes) / sizeof(double);
  setup.reference = load_bench_reference(options.reference_file);
  return setup;
}

Json machine_json(const coupling::MachineDescription& machine) {
  return {{"cpu_model", machine.cpu_model},
          {"logical_cpus", machine.logical_cpus},
          {"openmp_max_threads", machine.openmp_max_threads},
          {"omp_wait_policy", machine.omp_wait_policy},
          {"load_average", machine.load_average},
          {"last_level_cache_bytes", machine.last_level_cache_bytes}};
}

std::string number_or_dash(const Json& value, int decimals, const std::string& suffix = "") {
  return value.is_null() ? "-" : fixed(value.get<double>(), decimals) + suffix;
}

template <typename Cell>
std::vector<std::string> per_run(const Json& runs, Cell cell) {
  std::vector<std::string> cells;
  for (const auto& run : runs) cells.push_back(cell(run));
  return cells;
}

void print_fluid_rows(const Json& runs, std::size_t index) {
  const auto& first = runs.front()["fluid"][index];
  const std::string name = "fluid " + lattice_name(first["lattice"].get<std::array<int, 3>>());
  const auto field = [&](const char* key, int decimals, const std::string& suffix = "") {
    return per_run(runs, [&](const Json& run) {
      return number_or_dash(run["fluid"][index][key], decimals, suffix);
    });
  };
  print_row(name + ", optimised kernel (MLUPS)", field("optimised_mlups", 1));
  print_row(name + ", reference kernel (MLUPS)", field("reference_mlups", 2));
  print_row("  optimised / reference", field("optimised_over_reference", 1, "x"));
  print_row("  fraction of the DRAM roofline",
            per_run(runs,
                    [&](const Json& run) {
                      return fixed(100.0 * run["fluid"][index]["roofline_fraction"].get<double>(),
                                   0) +
                             " %";
                    }),
            index == 1 ? "target >= " + fixed(100.0 * kRooflineTarget, 0) + " % (large lattice)"
                       : "in cache: may exceed 100 %");
  if (index == 0) print_row("  vs the reference (below)", field("speedup_vs_reference", 1, "x"));
  print_row(name + ", single precision (MLUPS)", field("single_mlups", 1));
  print_row("  single / double", field("single_over_double", 2, "x"));
  print_row("  fraction of the roofline at 152 B/node", per_run(runs, [&](const Json& run) {
              return fixed(100.0 * run["fluid"][index]["single_roofline_fraction"].get<double>(),
                           0) +
                     " %";
            }));
}

void print_coupled_rows(const Json& runs, std::size_t index, bool verbose) {
  const auto& first = runs.front()["coupled"][index];
  const std::string name =
      "coupled step, " + std::to_string(first["vertices"].get<int>()) + " vertices (ms)";
  print_row(name,
            per_run(runs,
                    [&](const Json& run) {
                      return fixed(run["coupled"][index]["ms_per_step"].get<double>(), 3);
                    }),
            first["vertices"] == 642
                ? "target <= " + fixed(kCoupledTargetMsOneCore, 1) + " ms on one core"
                : "");
  if (first["vertices"] == 642) {
    print_row("  vs the reference (below)", per_run(runs, [&](const Json& run) {
                return number_or_dash(run["coupled"][index]["speedup_vs_reference"], 1, "x");
              }));
  }
  if (!verbose) return;
  for (const auto& [phase, value] : first["phases_ms_per_step"].items()) {
    // Copied into the lambda: clang 14 (the fuzz build) cannot capture a structured binding.
    print_row("    " + phase + " (ms)", per_run(runs, [&, name = phase](const Json& run) {
                return fixed(run["coupled"][index]["phases_ms_per_step"][name].get<double>(), 3);
              }));
  }
}

std::string percent(const Json& shares, const char* key) {
  return fixed(100.0 * shares[key].get<double>(), 0);
}

void print_suspension_rows(const Json& runs, std::size_t index, bool verbose) {
  const auto& first = runs.front()["suspension"][index];
  const auto field = [&](const char* key, int decimals, const std::string& suffix = "") {
    return per_run(runs, [&](const Json& run) {
      return fixed(run["suspension"][index][key].get<double>(), decimals) + suffix;
    });
  };
  print_row("suspension, " + std::to_string(first["cells"].get<int>()) + " x " +
                std::to_string(first["vertices"].get<int>() / first["cells"].get<int>()) +
                " vertices (ms)",
            field("ms_per_step", 2));
  print_row("  per cell (ms)", field("ms_per_step_per_cell", 3));
  if (index > 0) {
    print_row("  per cell / fewest cells'", field("per_cell_over_fewest_cells", 2, "x"),
              "1.00x: linear in the cells");
  }
  print_row("  fluid/membrane/IBM/contact (%)", per_run(runs, [&](const Json& run) {
              const auto& shares = run["suspension"][index]["shares"];
              return percent(shares, "fluid") + "/" + percent(shares, "membrane") + "/" +
                     percent(shares, "ibm") + "/" + percent(shares, "contact");
            }));
  if (!verbose) return;
  print_row("    vertex pairs in contact range", per_run(runs, [&](const Json& run) {
              return std::to_string(run["suspension"][index]["contact_pairs"].get<std::size_t>());
            }));
}

void print_text(const Json& report, bool verbose) {
  const auto& machine = report["machine"];
  const double cache_MiB = machine["last_level_cache_bytes"].get<double>() / (1 << 20);
  std::printf("rbcsim bench: %s, %d logical CPUs, last-level cache %s\n",
              machine["cpu_model"].get<std::string>().c_str(), machine["logical_cpus"].get<int>(),
              cache_MiB > 0.0 ? (fixed(cache_MiB, 0) + " MiB").c_str() : "unknown");
  std::printf("OMP_WAIT_POLICY=%s, load average %s (other processes lower every figure)\n\n",
              machine["omp_wait_policy"].get<std::string>().c_str(),
              machine["load_average"].get<std::string>().c_str());
  const auto& runs = report["runs"];
  print_row("", per_run(runs, [](const Json& run) {
              return std::to_string(run["threads"].get<int>()) + " thread(s)";
            }));
  print_row("memory bandwidth, STREAM triad (GB/s)", per_run(runs, [](const Json& run) {
              return fixed(run["memory_bandwidth_GB_per_s"].get<double>(), 1);
            }));
  print_row("DRAM roofline at 304 B/node (MLUPS)", per_run(runs, [](const Json& run) {
              return fixed(run["roofline_mlups"].get<double>(), 1);
            }));
  for (std::size_t index = 0; index < runs.front()["fluid"].size(); ++index) {
    print_fluid_rows(runs, index);
  }
  for (std::size_t index = 0; index < runs.front()["coupled"].size(); ++index) {
    print_coupled_rows(runs, index, verbose);
  }
  for (std::size_t index = 0; index < runs.front()["suspension"].size(); ++index) {
    print_suspension_rows(runs, index, verbose);
  }
  const auto& reference = report["reference"];
  std::printf(
      "\nreference: %s, measured on %s (\"-\": no figure for that case or thread count; "
      "a ratio means something only on that machine)\n",
      reference["label"].get<std::string>().c_str(),
      reference["machine"].get<std::string>().c_str());
  if (!reference["provenance"].get<std::string>().empty()) {
    std::printf("  %s\n", reference["provenance"].get<std::string>().c_str());
  }
}

Json reference_json(const BenchReference& reference) {
  const auto per_threads = [](const std::map<int, double>& figures) {
    Json object = Json::object();
    for (const auto& [threads, value] : figures) object[std::to_string(threads)] = value;
    return object;
  };
  return {
      {"label", reference.label},
      {"machine", reference.machine},
      {"provenance", reference.provenance},
      {"coupled_ms_per_step_642_vertices", per_threads(reference.coupled_ms_per_step_642_vertices)},
      {"fluid_mlups_40x40x20", per_threads(reference.fluid_mlups_40x40x20)}};
}

// The bench's --config, --preset and --set, for the paper cases' command lines.
std::vector<std::string> forwarded_config_arguments(const config::ConfigRequest& request) {
  std::vector<std::string> arguments;
  for (const auto& file : request.files)
    arguments.insert(arguments.end(), {"--config", file.string()});
  if (request.preset) arguments.insert(arguments.end(), {"--preset", *request.preset});
  for (const auto& assignment : request.assignments) {
    arguments.insert(arguments.end(), {"--set", assignment});
  }
  return arguments;
}

// The first executable file `name` in a directory of PATH, if any.
std::optional<std::filesystem::path> on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string_view rest = path == nullptr ? "" : path;
  while (!rest.empty()) {
    const auto end = std::min(rest.find(':'), rest.size());
    const auto candidate = std::filesystem::path(rest.substr(0, end)) / name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
    rest.remove_prefix(std::min(end + 1, rest.size()));
  }
  return std::nullopt;
}

// The launcher of --paper-cases-processes: a build with MPI (one without would run N independent
// copies of each case) and mpiexec on PATH.
std::filesystem::path paper_case_launcher() {
  if (!parallel::built_with_mpi()) {
    throw InputError("--paper-cases-processes",
                     "this rbcsim was built without MPI (the CMake option RBCSIM_MPI)");
  }
  const auto mpiexec = on_path("mpiexec");
  if (!mpiexec) {
    throw InputError("--paper-cases-processes", "needs mpiexec on PATH (Debian: openmpi-bin)");
  }
  return *mpiexec;
}

// The paper cases' request, checked before a minute of measurements: names, --output and the
// launcher of --paper-cases-processes.
std::optional<PaperCaseRequest> paper_case_request(const BenchOptions& options) {
  if (options.paper_cases.empty()) {
    if (options.paper_case_processes > 1) {
      throw InputError("--paper-cases-processes", "needs --paper-cases (the cases to run)");
    }
    return std::nullopt;
  }
  PaperCaseRequest request;
  request.names = parse_paper_case_names(options.paper_cases);
  if (options.common.output_directory.empty()) {
    throw InputError("--paper-cases", "needs --output DIR (each case's run directory goes there)");
  }
  request.directory = options.common.output_directory / "paper_cases";
  request.forwarded_arguments = forwarded_config_arguments(options.common.config);
  request.progress = !options.common.quiet;
  request.processes = options.paper_case_processes;
  if (request.processes > 1) request.mpiexec = paper_case_launcher();
  return request;
}

// Runs that did not end with exit 0, for the bench's own failure after everything is written.
std::vector<std::string> failed_paper_case_runs(const Json& entries) {
  std::vector<std::string> failed;
  const auto add_if_failed = [&](const Json& measured) {
    if (measured.is_null() || measured["exit_code"] == 0) return;
    failed.push_back(measured["directory"].get<std::string>() + " (exit " +
                     measured["exit_code"].dump() + ")");
  };
  for (const auto& entry : entries) {
    for (const auto& run : entry["runs"]) {
      add_if_failed(run["now"]);
      add_if_failed(run["before"]);
    }
    if (!entry["processes"].is_null()) add_if_failed(entry["processes"]["run"]);
  }
  return failed;
}

void run_bench(const BenchOptions& options) {
  if (options.ranks) {
    RankBenchRequest request;
    request.lattice = {options.rank_lattice[0], options.rank_lattice[1], options.rank_lattice[2]};
    request.block_planes = options.block_planes;
    request.cells = options.rank_cells;
    request.threads_per_process = options.common.threads > 0 ? options.common.threads : 1;
    request.json = options.common.json;
    request.quiet = options.common.quiet;
    request.output_directory = options.common.output_directory;
    run_rank_bench(request);
    return;
  }
  if (parallel::Communicator::world().size() > 1) {
    throw InputError("bench",
                     "on several processes it measures the distributed lattice only: "
                     "add --ranks");
  }
  auto paper_request = paper_case_request(options);
  const auto machine = coupling::describe_machine();
  const auto setup = bench_setup(options, machine);
  const int all_threads =
      options.common.threads > 0 ? options.common.threads : machine.logical_cpus;
  std::vector<int> thread_counts = {1};
  if (all_threads > 1) thread_counts.push_back(all_threads);

  Json runs = Json::array();
  for (const int threads : thread_counts) {
    if (!options.common.quiet && !options.common.json) {
      std::cerr << "rbcsim bench: measuring with " << threads << " thread(s)...\n";
    }
    runs.push_back(measure_at(threads, setup));
  }
  Json paper_cases = Json::array();
  if (paper_request) {
    paper_request->thread_counts = thread_counts;
    auto discocyte_request = options.common.config;
    discocyte_request.morphology = "discocyte";
    paper_cases = run_paper_cases(config::resolve_config(discocyte_request), *paper_request);
  }
  const Json report = {{"machine", machine_json(machine)},
                       {"ibm_kernel", setup.ibm_kernel},
                       {"cytoplasm_viscosity_ratio", setup.cytoplasm.viscosity_ratio},
                       {"cytoplasm_update_dx", setup.cytoplasm.update_lu},
                       {"reference", reference_json(setup.reference)},
                       {"targets",
                        {{"roofline_fraction_large_lattice", kRooflineTarget},
                         {"coupled_ms_per_step_one_core", kCoupledTargetMsOneCore}}},
                       {"runs", runs},
                       {"paper_cases", paper_cases}};
  if (!options.common.output_directory.empty()) {
    std::filesystem::create_directories(options.common.output_directory);
    io::write_text_atomically(options.common.output_directory / "bench.json",
                              report.dump(2) + "\n");
  }
  if (options.common.json) {
    std::cout << report.dump(2) << '\n';
  } else {
    print_text(report, options.common.verbose);
    if (!paper_cases.empty()) print_paper_cases(paper_cases);
  }
  if (const auto failed = failed_paper_case_runs(paper_cases); !failed.empty()) {
    std::string list;
    for (const auto& run : failed) list += (list.empty() ? "" : ", ") + run;
    throw RuntimeFailure("bench: paper case runs failed: " + list + "; their logs end in .log");
  }
}

void attach_bench_command(CLI::App& application) {
  auto* command = application.add_subcommand(
      "bench",
      "Measure memory bandwidth, fluid MLUPS and the coupled step, with ratios to a reference "
      "measured on a named machine (HemoCell side by side on the project machine by default)");
  auto options = std::make_shared<BenchOptions>();
  add_common_options(command, options->common);
  command
      ->add_option("--large-lattice", options->large_lattice,
                   "Extent of the out-of-cache lattice (default: twice the last-level cache)")
      ->expected(3)
      ->type_name("NX NY NZ")
      ->check(whole_number_at_least(1));
  command
      ->add_option("--cells", options->suspension_cell_counts,
                   "Cell counts of the suspensions measured, 642 vertices each, in a row of "
                   "periodic blocks with contact on (docs/commands/bench.md)")
      ->default_str("1 10 50 100")
      ->type_name("N ...")
      ->check(whole_number_at_least(1));
  command
      ->add_option("--reference", options->reference_file,
                   "JSON file of another code's figures on the same cases and the machine they "
                   "were measured on (docs/commands/bench.md); default: "
                   "share/reference/hemocell_bench.json")
      ->type_name("FILE");
  command
      ->add_option("--paper-cases", options->paper_cases,
                   "Also time the paper's runs end to end, 1 and all threads, beside their "
                   "settings before the speed work where a setting restores them: \"all\" "
                   "(capillary, mills, shear: about an hour on 2 cores) or names, comma-separated "
                   "(capillary-fine: hours); needs --output")
      ->type_name("NAMES");
  command
      ->add_option("--paper-cases-processes", options->paper_case_processes,
                   "Also run each paper case as `mpiexec -n N rbcsim ...`, one thread per "
                   "process, against its one-process, one-thread run (needs a build with MPI "
                   "and mpiexec on PATH)")
      ->default_str("1")
      ->type_name("N")
      ->check(whole_number_at_least(1));
  command->add_flag("--ranks", options->ranks,
                    "Measure only the lattice distributed over the processes of `mpirun -np N`: "
                    "ms per step against one process in the same run, the halo's share, bytes "
                    "and messages, and a weak-scaling projection to 512 processes");
  command
      ->add_option("--ranks-lattice", options->rank_lattice,
                   "Extent of the lattice --ranks distributes")
      ->default_str("128 128 128")
      ->expected(3)
      ->type_name("NX NY NZ")
      ->check(whole_number_at_least(1));
  command
      ->add_option("--block-planes", options->block_planes,
                   "z-planes per block of the distributed lattice (--ranks)")
      ->default_str("8")
      ->check(whole_number_at_least(2));
  command
      ->add_option("--ranks-cells", options->rank_cells,
                   "Spheres of 642 vertices whose stencils, spreading and interpolation --ranks "
                   "also measures on the distributed lattice (0: the fluid alone)")
      ->default_str("8")
      ->check(whole_number_at_least(0));
  command->footer(
      "--threads N sets the 'all threads' column (default: every logical CPU); --output DIR also "
      "writes DIR/bench.json; --verbose adds the time of each phase of the coupled step.");
  command->callback([options] { run_bench(*options); });
}

const bool registered = register_command({"bench", 95, attach_bench_command, true});

}  // namespace
}  // namespace rbcsim::cli::bench_command
