// A cell list (linked-cell binning) over points in um, so that a short-range search costs O(points)
// instead of O(points^2). Along a periodic axis positions are not wrapped (cells travel
// continuously, coupling/cell.hpp); the list wraps the bin index and the caller takes the minimum
// image of each separation (PeriodicBox).
//
// Deterministic: each bin lists its points in increasing index, and the neighbour bins of a point
// are visited in a fixed order, so a sum over neighbours does not depend on the thread count.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/vec3.hpp"

namespace rbcsim::contact {

// The period along each axis in um; 0: not periodic.
struct PeriodicBox {
  std::array<double, 3> length_um{0.0, 0.0, 0.0};

  // The separation with each periodic component brought into [-L/2, L/2]. Inline, and without
  // the library's round() where the component is already inside (round(q) = 0 exactly for
  // |q| < 1/2): the contact search takes it for every corner of every triangle it tries.
  Vec3 minimum_image(Vec3 separation_um) const {
    for (int axis = 0; axis < 3; ++axis) {
      const double length = length_um[axis];
      if (!(length > 0.0)) continue;
      const double periods = separation_um[axis] / length;
      if (std::abs(periods) < 0.5) continue;
      separation_um[axis] -= length * std::round(periods);
    }
    return separation_um;
  }
};

class CellList {
 public:
  // A stretch of one bin's points that belong to one group (a cell).
  struct Run {
    std::uint32_t group = 0;
    std::uint32_t begin = 0;  // into points()
    std::uint32_t end = 0;
  };
  struct Neighbours {
    std::array<std::size_t, 27> bins{};
    // Per bin, the whole periods (um) to add to the wrapped position of a point there to place
    // it next to the centre bin (zero off periodic axes): see wrapped().
    std::array<Vec3, 27> shift_um{};
    std::size_t count = 0;
  };

  // Bins `points_um` into boxes of side >= reach_um (along a periodic axis: the period divided
  // into whole bins). `groups` (empty, or one per point, non-decreasing: the points grouped cell
  // by cell) splits each bin's points into runs of one group. Throws std::invalid_argument for
  // reach_um <= 0, a period below it, or groups that are not grouped.
  void build(std::span<const Vec3> points_um, double reach_um, const PeriodicBox& box,
             std::span<const std::uint32_t> groups = {});

  std::size_t bin_count() const { return bin_start_.empty() ? 0 : bin_start_.size() - 1; }
  // The point indices of all bins, bin after bin, increasing within a bin.
  std::span<const std::uint32_t> points() const { return bin_points_; }
  std::span<const std::uint32_t> bin(std::size_t b) const {
    return std::span<const std::uint32_t>(bin_points_)
        .subspan(bin_start_[b], bin_start_[b + 1] - bin_start_[b]);
  }
  std::span<const Run> runs(std::size_t b) const {
    return std::span<const Run>(runs_).subspan(run_start_[b], run_start_[b + 1] - run_start_[b]);
  }
  // The bin itself and the up to 26 adjacent ones, each once, in a fixed order: every point
  // within reach_um of a point of bin b lies in one of them.
  Neighbours neighbours_of_bin(std::size_t b) const;
  // Each point wrapped into the period along the periodic axes. When every periodic axis has
  // three bins or more, wrapped(i) - (wrapped(j) + shift_um of j's bin) is the minimum image of
  // the separation for every pair within reach (has_exact_shifts); otherwise take the minimum
  // image pair by pair.
  const Vec3& wrapped(std::size_t point) const { return wrapped_um_[point]; }
  bool has_exact_shifts() const { return exact_shifts_; }

  // Calls visit(j) for every point j in the bins around `point_um` (its bin and the adjacent
  // ones): a superset of the points within reach_um of it.
  template <class Visit>
  void for_each_candidate(const Vec3& point_um, const Visit& visit) const {
    const auto neighbours = neighbours_of_coordinates(bin_coordinates(point_um));
    for (std::size_t n = 0; n < neighbours.count; ++n) {
      for (const std::uint32_t j : bin(neighbours.bins[n])) visit(j);
    }
  }
  // The same points run by run: visit(run, shift_um) for every run of one group in those bins,
  // with the shift of its bin (Neighbours::shift_um: the wrapped(j) of the run's points plus
  // shift_um lie next to the bin of `point_um`), so a caller can skip a group whole.
  template <class Visit>
  void for_each_candidate_run(const Vec3& point_um, const Visit& visit) const {
    const auto neighbours = neighbours_of_coordinates(bin_coordinates(point_um));
    for (std::size_t n = 0; n < neighbours.count; ++n) {
      for (const Run& run : runs(neighbours.bins[n])) visit(run, neighbours.shift_um[n]);
    }
  }

 private:
  // The bin coordinates of `point_um`, wrapped along a periodic axis and clamped to the bins
  // along another (a point outside the box the list was built on still finds the edge).
  std::array<int, 3> bin_coordinates(const Vec3& point_um) const;
  Neighbours neighbours_of_coordinates(const std::array<int, 3>& centre) const;

  std::array<int, 3> bins_per_axis_{0, 0, 0};
  std::array<double, 3> origin_um_{0.0, 0.0, 0.0};
  std::array<double, 3> side_um_{1.0, 1.0, 1.0};
  std::array<bool, 3> periodic_{false, false, false};
  std::array<double, 3> period_um_{0.0, 0.0, 0.0};
  bool exact_shifts_ = true;
  std::vector<Vec3> wrapped_um_;
  std::vector<std::uint32_t> bin_start_;   // points of bin b: bin_points_[start[b] .. start[b+1])
  std::vector<std::uint32_t> bin_points_;  // point indices, increasing within a bin
  std::vector<std::uint32_t> run_start_;   // runs of bin b: runs_[run_start[b] .. run_start[b+1])
  std::vector<Run> runs_;
};

}  // namespace rbcsim::contact
