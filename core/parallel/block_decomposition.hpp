// The global lattice cut into blocks of whole z-planes, and the blocks dealt to processes. z is the
// slowest index of the grid (lattice_grid.hpp), so a block, and each of its faces, is one
// contiguous range of nodes: a halo is a copy, not a gather. Blocks have a fixed size, which the
// rank count does not change (the last block takes the remainder of nz), so everything computed
// per block (sums, hashes) is the same on any number of processes.
//
// The deal: each process gets a contiguous run of blocks (a space-filling curve in one dimension),
// the runs cut where the cumulative block weight (for instance fluid nodes) crosses r / size of the
// total, with at least one block each. Integer weights, so the cut is exact on every process.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace rbcsim::parallel {

class BlockDecomposition {
 public:
  // nz planes in blocks of block_planes (>= 2: a process's slab must be at least as thick as the
  // halo it lends), dealt to `ranks` processes by `block_weights` (one per block, >= 0; empty: all
  // equal). Throws rbcsim::InputError naming the block decomposition when a block is thinner than
  // 2 planes or there are fewer blocks than processes (with the numbers).
  BlockDecomposition(int nz, int block_planes, int ranks,
                     std::span<const std::int64_t> block_weights = {});

  int plane_count() const { return nz_; }
  int block_planes() const { return block_planes_; }
  int block_count() const { return static_cast<int>(block_z_begin_.size()) - 1; }
  int rank_count() const { return static_cast<int>(rank_block_begin_.size()) - 1; }

  // Planes [block_z_begin(b), block_z_begin(b + 1)) form block b.
  int block_z_begin(int block) const { return block_z_begin_[block]; }
  // Blocks [first_block(r), first_block(r + 1)) belong to rank r.
  int first_block(int rank) const { return rank_block_begin_[rank]; }
  // The planes of rank r: [z_begin(r), z_end(r)).
  int z_begin(int rank) const { return block_z_begin_[rank_block_begin_[rank]]; }
  int z_end(int rank) const { return block_z_begin_[rank_block_begin_[rank + 1]]; }
  int owner_of_plane(int z) const;

 private:
  int nz_;
  int block_planes_;
  std::vector<int> block_z_begin_;     // block_count + 1 entries
  std::vector<int> rank_block_begin_;  // ranks + 1 entries
};

}  // namespace rbcsim::parallel
