// A box of nx * ny * nz lattice nodes with x fastest: index = x + nx * (y + ny * z). Every field of
// the fluid (populations per direction, density, velocity components, force density, node kinds)
// is a plain array in this order, so kernels run contiguous loops over x.
#pragma once

#include <array>
#include <cstddef>

namespace rbcsim::lattice {

class LatticeGrid {
 public:
  // Throws rbcsim::InputError unless every extent is at least 1.
  LatticeGrid(int nx, int ny, int nz);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int nz() const { return nz_; }
  std::size_t node_count() const { return node_count_; }
  std::size_t row_count() const { return static_cast<std::size_t>(ny_) * nz_; }
  // Whether a sweep over the lattice is worth an OpenMP fork-join: below ~4096 nodes a step takes
  // a fraction of a millisecond and the threads' start and barrier, on a busy machine, cost more.
  // Kernels give each node to one thread whatever the split, so this never changes a result.
  bool worth_threads() const { return node_count_ >= 4096; }

  std::size_t index(int x, int y, int z) const {
    return static_cast<std::size_t>(x) + static_cast<std::size_t>(nx_) * (y + std::size_t(ny_) * z);
  }
  std::array<int, 3> coordinates(std::size_t node) const;

  // The node at (x + dx, y + dy, z + dz) with every axis wrapped periodically.
  std::size_t periodic_neighbour(std::size_t node, const std::array<int, 3>& offset) const;

  // Wraps one coordinate into [0, extent).
  static int wrap(int coordinate, int extent) {
    const int remainder = coordinate % extent;
    return remainder < 0 ? remainder + extent : remainder;
  }
  // wrap for a coordinate at most one node outside [0, extent): a comparison instead of the
  // remainder's division, which in the optimised kernel's 19 pointers per run of the streaming
  // step cost about a third as much as colliding a 40-node row.
  static int wrap_by_one(int coordinate, int extent) {
    return coordinate < 0 ? coordinate + extent
                          : (coordinate >= extent ? coordinate - extent : coordinate);
  }

 private:
  int nx_;
  int ny_;
  int nz_;
  std::size_t node_count_;
};

}  // namespace rbcsim::lattice
