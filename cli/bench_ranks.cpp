#include "bench_ranks.hpp"

#include "coupling/benchmark.hpp"
#include "io/atomic_file.hpp"
#include "mesh/icosphere.hpp"
#include "parallel/benchmark.hpp"
#include "parallel/communicator.hpp"

#include <cstdio>
#include <iostream>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rbcsim::cli {

namespace {

using Json = nlohmann::ordered_json;

// Even: as many streaming steps as local ones (only the former exchange with the AA kernel).
constexpr std::size_t kStepsPerBatch = 6;
constexpr int kBatches = 5;
constexpr int kProjectedProcesses = 512;
// The network of the projection's second column: assumed, not measured (a 100 Gb/s InfiniBand
// EDR link and a typical MPI latency on it).
constexpr double kAssumedNetworkBytesPerS = 12.5e9;
constexpr double kAssumedMessageLatencyS = 1.5e-6;

Json timing_json(const parallel::DistributedFluidTiming& timing) {
  return {{"processes", timing.processes},
          {"threads_per_process", timing.threads_per_process},
          {"ms_per_step", timing.ms_per_step},
          {"mlups", timing.mlups},
          {"halo_ms_per_step", timing.halo_ms_per_step},
          {"halo_share", timing.halo_ms_per_step / timing.ms_per_step},
          {"halo_bytes_per_step_per_process", timing.halo_bytes_per_step},
          {"halo_messages_per_step_per_process", timing.halo_messages_per_step},
          {"largest_slab_planes", timing.largest_slab_planes},
          {"ibm_ms_per_step", timing.ibm_ms_per_step}};
}

// Weak scaling: every process keeps the slab it has here, so the lattice grows along z.
Json weak_scaling_projection(const parallel::DistributedFluidTiming& all) {
  const double compute_ms = all.ms_per_step - all.halo_ms_per_step;
  const double network_ms = 1e3 * (all.halo_bytes_per_step / kAssumedNetworkBytesPerS +
                                   all.halo_messages_per_step * kAssumedMessageLatencyS);
  return {
      {"processes", kProjectedProcesses},
      {"lattice", {all.lattice[0], all.lattice[1], kProjectedProcesses * all.largest_slab_planes}},
      {"assumption",
       "Each process keeps the slab measured here and its compute time per step (the measured "
       "step less the halo). Slabs have two neighbours whatever the process count, so a "
       "process's halo stays the measured bytes and messages per step. The exchange is charged "
       "at the rate measured here (shared memory, one machine) and at an assumed network of "
       "12.5 GB/s and 1.5 us per message (100 Gb/s InfiniBand), not measured. Contention on the "
       "network and collective operations are not modelled; output and cells are not included."},
      {"efficiency_at_measured_exchange", compute_ms / all.ms_per_step},
      {"efficiency_at_assumed_network", compute_ms / (compute_ms + network_ms)}};
}

void print_set(const Json& set, const std::string& title) {
  std::printf("  %s\n", title.c_str());
  for (const auto& run : set["runs"]) {
    std::printf(
        "    %2d process(es): %8.3f ms/step  %7.1f MLUPS  halo %6.3f ms (%4.1f %%)  IBM %6.3f ms, "
        "%.2f MB and %.1f messages per step per process\n",
        run["processes"].get<int>(), run["ms_per_step"].get<double>(), run["mlups"].get<double>(),
        run["halo_ms_per_step"].get<double>(), 100.0 * run["halo_share"].get<double>(),
        run["ibm_ms_per_step"].get<double>(),
        run["halo_bytes_per_step_per_process"].get<double>() / 1e6,
        run["halo_messages_per_step_per_process"].get<double>());
  }
  std::printf("    undivided lattice, one process: %8.3f ms/step (IBM %.3f ms)\n",
              set["undivided"]["ms_per_step"].get<double>(),
              set["undivided"]["ibm_ms_per_step"].get<double>());
  std::printf(
      "    strong scaling: %.2fx on %d processes, %.0f %% of linear (%.2fx the undivided "
      "lattice)\n",
      set["speedup"].get<double>(), set["runs"][1]["processes"].get<int>(),
      100.0 * set["parallel_efficiency"].get<double>(),
      set["speedup_over_undivided"].get<double>());
}

void print_text(const Json& report) {
  std::printf(
      "rbcsim bench --ranks: %s, lattice %dx%dx%d in blocks of %d planes, %d thread(s) "
      "per process\n",
      report["machine"]["cpu"].get<std::string>().c_str(), report["lattice"][0].get<int>(),
      report["lattice"][1].get<int>(), report["lattice"][2].get<int>(),
      report["block_planes"].get<int>(), report["threads_per_process"].get<int>());
  print_set(report["fluid"], "fluid alone:");
  if (!report["with_cells"].is_null()) {
    print_set(report["with_cells"],
              "with " + report["with_cells"]["cells"].dump() + " cells of " +
                  report["with_cells"]["vertices_per_cell"].dump() +
                  " vertices (stencils, spreading, interpolation; every process holds them all):");
  }
  const auto& weak = report["fluid"]["weak_scaling_projection"];
  std::printf(
      "  weak scaling of the fluid projected to %d processes: %.0f %% (exchange as measured "
      "here), %.0f %% (assumed network; see --json for the assumptions)\n",
      weak["processes"].get<int>(), 100.0 * weak["efficiency_at_measured_exchange"].get<double>(),
      100.0 * weak["efficiency_at_assumed_network"].get<double>());
}

// Spheres of 642 vertices, radius 4 lattice spacings, spread over the box along z (so that every
// slab holds some) and alternately across x and y.
std::vector<Vec3> cell_points(const std::array<int, 3>& lattice, int cells) {
  const mesh::TriangleMesh sphere = mesh::unit_icosphere(3);
  std::vector<Vec3> points;
  for (int k = 0; k < cells; ++k) {
    const Vec3 centre(lattice[0] * (0.25 + 0.5 * (k % 2)),
                      lattice[1] * (0.25 + 0.5 * ((k / 2) % 2)), lattice[2] * (k + 0.5) / cells);
    for (const Vec3& vertex : sphere.positions_um) points.push_back(centre + 4.0 * vertex);
  }
  return points;
}

// All processes, then rank 0 alone (distributed over one process, then undivided) while the others
// wait: one set of the report. Rank 0 gets it, the others null.
Json scaling_set(const parallel::Communicator& world, const RankBenchRequest& request,
                 std::span<const Vec3> points) {
  const auto all = parallel::measure_distributed_fluid(world, request.lattice, request.block_planes,
                                                       kStepsPerBatch, kBatches,
                                                       request.threads_per_process, points);
  std::optional<parallel::DistributedFluidTiming> alone;
  std::optional<parallel::DistributedFluidTiming> undivided;
  if (world.is_root()) {
    alone = parallel::measure_distributed_fluid(parallel::Communicator::self(), request.lattice,
                                                request.block_planes, kStepsPerBatch, kBatches,
                                                request.threads_per_process, points);
    undivided = parallel::measure_undivided_fluid(request.lattice, kStepsPerBatch, kBatches,
                                                  request.threads_per_process, points);
  }
  world.barrier();
  if (!world.is_root()) return nullptr;
  const double speedup = alone->ms_per_step / all.ms_per_step;
  return {{"points", points.size()},
          {"runs", {timing_json(*alone), timing_json(all)}},
          {"undivided",
           {{"processes", 1},
            {"ms_per_step", undivided->ms_per_step},
            {"mlups", undivided->mlups},
            {"ibm_ms_per_step", undivided->ibm_ms_per_step}}},
          {"speedup", speedup},
          {"speedup_over_undivided", undivided->ms_per_step / all.ms_per_step},
          {"parallel_efficiency", speedup / all.processes},
          {"weak_scaling_projection", weak_scaling_projection(all)}};
}

}  // namespace

Json run_rank_bench(const RankBenchRequest& request) {
  const auto world = parallel::Communicator::world();
  if (world.is_root() && !request.quiet && !request.json) {
    std::cerr << "rbcsim bench --ranks: " << world.size() << " process(es), then one alone...\n";
  }
  Json fluid = scaling_set(world, request, {});
  Json with_cells = nullptr;
  if (request.cells > 0) {
    const std::vector<Vec3> points = cell_points(request.lattice, request.cells);
    with_cells = scaling_set(world, request, points);
    if (world.is_root()) {
      with_cells["cells"] = request.cells;
      with_cells["vertices_per_cell"] = points.size() / request.cells;
    }
  }
  if (!world.is_root()) return nullptr;

  const auto machine = coupling::describe_machine();
  Json report = {{"machine",
                  {{"cpu", machine.cpu_model},
                   {"logical_cpus", machine.logical_cpus},
                   {"load_average", machine.load_average}}},
                 {"mpi", parallel::MpiSession::active()},
                 {"processes", world.size()},
                 {"threads_per_process", request.threads_per_process},
                 {"lattice", request.lattice},
                 {"block_planes", request.block_planes},
                 {"fluid", fluid},
                 {"with_cells", with_cells}};
  if (!request.output_directory.empty()) {
    std::filesystem::create_directories(request.output_directory);
    io::write_text_atomically(request.output_directory / "bench.json", report.dump(2) + "\n");
  }
  if (request.json) {
    std::cout << report.dump(2) << '\n';
  } else {
    print_text(report);
  }
  return report;
}

}  // namespace rbcsim::cli
