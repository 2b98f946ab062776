// `rbcsim bench --ranks` under `mpirun -np N`: the distributed lattice's strong scaling on this
// machine (N processes against one, in the same run), the halo's share of a step, its bytes and
// messages, and a weak-scaling projection to 512 processes with its assumptions written out
// (docs/commands/bench.md, docs/performance.md).
#pragma once

#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace rbcsim::cli {

struct RankBenchRequest {
  std::array<int, 3> lattice = {128, 128, 128};
  int block_planes = 8;
  int cells = 8;  // spheres of 642 vertices measured with the fluid; 0: the fluid alone
  int threads_per_process = 1;
  bool json = false;
  bool quiet = false;
  std::filesystem::path output_directory;  // empty: no bench.json
};

// Collective over every process of the run. Rank 0 prints (text or --json) and writes
// DIR/bench.json; returns the report on rank 0, null elsewhere.
nlohmann::ordered_json run_rank_bench(const RankBenchRequest& request);

}  // namespace rbcsim::cli
