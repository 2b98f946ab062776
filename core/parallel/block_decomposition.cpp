#include "parallel/block_decomposition.hpp"

#include "common/errors.hpp"

#include <algorithm>
#include <numeric>
#include <string>

namespace rbcsim::parallel {

BlockDecomposition::BlockDecomposition(int nz, int block_planes, int ranks,
                                       std::span<const std::int64_t> block_weights)
    : nz_(nz), block_planes_(block_planes) {
  if (block_planes < 2) {
    throw InputError("block decomposition",
                     "blocks must be at least 2 planes thick (the halo's width), got " +
                         std::to_string(block_planes));
  }
  if (nz < 1 || ranks < 1) {
    throw InputError("block decomposition", "needs at least one plane and one process");
  }
  for (int z = 0; z < nz; z += block_planes) block_z_begin_.push_back(z);
  // A last block thinner than the halo joins the one before it.
  if (block_z_begin_.size() > 1 && nz - block_z_begin_.back() < 2) block_z_begin_.pop_back();
  block_z_begin_.push_back(nz);
  const int blocks = block_count();
  if (blocks < ranks) {
    throw InputError(
        "block decomposition",
        std::to_string(nz) + " planes in blocks of " + std::to_string(block_planes) + " make " +
            std::to_string(blocks) + " block(s) for " + std::to_string(ranks) +
            " processes; every process needs one: use thinner blocks (lattice.block_planes, "
            "bench --block-planes; at least 2) or fewer processes");
  }
  std::vector<std::int64_t> weights(block_weights.begin(), block_weights.end());
  if (weights.empty()) weights.assign(blocks, 1);
  if (static_cast<int>(weights.size()) != blocks ||
      std::any_of(weights.begin(), weights.end(), [](std::int64_t w) { return w < 0; })) {
    throw InputError("block decomposition",
                     "needs one weight >= 0 per block (" + std::to_string(blocks) + " blocks)");
  }
  const std::int64_t total = std::accumulate(weights.begin(), weights.end(), std::int64_t{0});
  rank_block_begin_.assign(ranks + 1, 0);
  rank_block_begin_[ranks] = blocks;
  std::int64_t cumulative = 0;
  int block = 0;
  for (int r = 1; r < ranks; ++r) {
    // Rank r starts at the first block whose preceding weight reaches r / ranks of the total
    // (compared as integers: cumulative * ranks >= r * total).
    while (block < blocks && cumulative * ranks < static_cast<std::int64_t>(r) * total) {
      cumulative += weights[block++];
    }
    const int earliest = rank_block_begin_[r - 1] + 1;
    const int latest = blocks - (ranks - r);
    rank_block_begin_[r] = std::clamp(block, earliest, latest);
    while (block < rank_block_begin_[r]) cumulative += weights[block++];
    while (block > rank_block_begin_[r]) cumulative -= weights[--block];
  }
}

int BlockDecomposition::owner_of_plane(int z) const {
  int rank = 0;
  while (rank + 1 < rank_count() && z >= z_begin(rank + 1)) ++rank;
  return rank;
}

}  // namespace rbcsim::parallel
